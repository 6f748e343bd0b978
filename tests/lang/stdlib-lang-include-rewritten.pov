// A file written with #fopen/#write, included, written again and included
// again is read again: the second #include sees the new text. (Found by
// strings.inc's Parse_String.)
#version 3.7;
#macro Emit(Text)
	#fopen F "include-rewritten.tmp" write
	#write (F, Text)
	#fclose F
	#include "include-rewritten.tmp"
#end
#declare A = Emit("1 + 2");
#declare B = Emit("10 * 3");
#declare C = Emit("A + B");
#debug concat(str(A, 0, 1), " ", str(B, 0, 1), " ", str(C, 0, 1), "\n")
#for (I, 1, 3)
	#fopen F "include-rewritten.tmp" write
	#write (F, "#debug \"pass ", str(I, 0, 0), "\\n\"\n")
	#fclose F
	#include "include-rewritten.tmp"
#end
