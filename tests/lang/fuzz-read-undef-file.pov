// checks #read whose file identifier is #undef'd among its own arguments: the
// read goes on from the file (found by fuzzing as a use after free; POV-Ray
// 3.7 itself crashes on this scene with a segmentation fault, so the output
// is lucent's: the values read, and F gone)
#version 3.7;
#fopen F "fuzz-read-undef-file.tmp" write
#write (F, "10, 20, 30\n")
#fclose F
#fopen F "fuzz-read-undef-file.tmp" read
#read (F, #undef F A, B)
#debug concat(str(A, 0, 0), " ", str(B, 0, 0), "\n")
#ifdef (F) #debug "F defined\n" #else #debug "F undefined\n" #end
