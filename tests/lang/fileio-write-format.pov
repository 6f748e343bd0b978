// checks the exact text #write produces for floats and vectors (by writing a #debug line and including it)
#version 3.7;
#fopen F "fileio-write-format.tmp" write
#write (F, "#debug \"[", 1.5, "] [", -2, "] [", 1/3, "] [", 1e10, "]\\n\"\n")
#write (F, "#debug \"[", <1, 2.5, -3>, "] [", 0, "] [", 123456.789, "]\\n\"\n")
#write (F, "#debug \"[", 1e-7, "] [", -0.5, "] [", <1/3, 2/3, 1>, "]\\n\"\n")
#fclose F
#include "fileio-write-format.tmp"
