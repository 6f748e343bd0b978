// checks several #read directives consuming one file in order, across lines
#version 3.7;
#fopen F "fileio-multiple-reads.tmp" write
#write (F, "1, 2, 3,\n4, 5,\n", "6\n")
#fclose F
#fopen F "fileio-multiple-reads.tmp" read
#read (F, A)
#read (F, B, C)
#read (F, D, E, G)
#fclose F
#debug concat(str(A, 0, 0), str(B, 0, 0), str(C, 0, 0), str(D, 0, 0), str(E, 0, 0), str(G, 0, 0), "\n")
