// checks #fopen append adding to the end of an existing file
#version 3.7;
#fopen F "fileio-append.tmp" write
#write (F, "1, 2,\n")
#fclose F
#fopen F "fileio-append.tmp" append
#write (F, "3, 4\n")
#fclose F
#fopen F "fileio-append.tmp" read
#read (F, A, B, C, D)
#fclose F
#debug concat(str(A, 0, 0), str(B, 0, 0), str(C, 0, 0), str(D, 0, 0), "\n")
