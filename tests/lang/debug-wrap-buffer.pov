// debug-wrap-buffer.pov: POV-Ray 3.7 passes #debug text through a buffer
// of 160 characters. When the 161st character arrives, the text is written
// up to its last blank if that blank is among the last 40 characters (the
// blank and what follows stay and begin the next line); otherwise the 160
// are written and end a line. The expected output is what POV-Ray 3.7.0.10
// prints.
#version 3.7;
#macro Str(C, N)
  #local S = "";
  #for (I, 1, N) #local S = concat(S, C); #end
  S
#end
// 80 "a", K "b", a space, 79 - K "c": a full buffer; then "ddddd".
#macro Probe(K)
  #debug concat(Str("a", 80), Str("b", K), " ", Str("c", 79 - K))
  #debug "ddddd\n"
#end
#for (K, 38, 42) Probe(K) #end
Probe(0) Probe(50) Probe(78) Probe(79)
// A line of 90 with a space at 71: the last 10 characters of the buffer are
// written as a line of their own.
#debug concat(Str("x", 70), " ", Str("y", 89))
#debug "zzzzz\n"
// Random messages that lucent used to break elsewhere.
#debug "            uvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyza bcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabc"
#debug "defghijklmnopqrstuvwxyzabcdefgh fghijklmnopqrst xyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyz"
#debug "abcdefghijklmnopqrstuvwxyzabcd efghijklmnopqrstuvwxyzabc wxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefgh abcdefghijklmnopqrstuvwxyzabcdefg"
#debug "hijkl\n"
#debug "|\n"
#debug concat("abcdefghijk defghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzab qrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdef hijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyza stuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghij", "k h")
#debug "ijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqr vwxy stuvwxy tuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopq"
#debug concat("rstuvwxyzabcdefgh xyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstu tuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmnopqrstuvwxyzabcdefghijklmn abcdefghijklmnopqrstuvwxyzabc", "defghijklmnopqrstuvwxyz")
#debug "abcdefghijklmnopqrstuv cdefghijklmnopqrstuvwxyz\n"
#debug "|\n"
#debug "                              abcdefghijklmnopqr mnopqrstuvwxyz pqrst klmnopqrstu  uvwxy efghijklmn   xyzabcdefghijkl"
#debug "mnopq  opqrstuvwxyzab"
#debug "cd fghij  ij stuvwxyzabcde   tuvwxyzabcdefgh   jklmnopq zabcdefghijklmn lmnopqrstuv"
#debug "wx defghi cdefghijklmn opqrstuvw   yzabcdefghij  opqrstuvwxyz"
#debug "abc ijk stu ghijklmn  j stuvwxyzab   abcd wxyzabcdefg opqrstuv  cdefgh klmn   no\n"
#debug "|\n"
