// checks #read of floats (signs, exponents), vectors of several sizes and strings
#version 3.7;
#fopen F "fileio-read-types.tmp" write
#write (F, "-1.5e2, 3, .25, <1,2>, <1,2,3,4>, <-1,-2,-3,-4,-5>, \"text with spaces\", \"\"\n")
#fclose F
#fopen F "fileio-read-types.tmp" read
#read (F, A, B, C, V2, V4, V5, S1, S2)
#fclose F
#debug concat(str(A, 0, 3), " ", str(B, 0, 3), " ", str(C, 0, 3), "\n")
#debug concat(vstr(2, V2, ",", 0, 1), " ", vstr(4, V4, ",", 0, 1), " ", vstr(5, V5, ",", 0, 1), "\n")
#debug concat("[", S1, "] [", S2, "]\n")
