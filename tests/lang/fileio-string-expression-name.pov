// checks #fopen with a file name built by a string expression, and two files open at once
#version 3.7;
#declare Base = "fileio-string-expression-name";
#fopen A concat(Base, "-a.tmp") write
#fopen B concat(Base, "-b.tmp") write
#write (A, "\"in a\"\n")
#write (B, "\"in b\"\n")
#fclose A
#fclose B
#fopen A concat(Base, "-a.tmp") read
#fopen B concat(Base, "-b.tmp") read
#read (B, SB)
#read (A, SA)
#fclose A
#fclose B
#debug concat(SA, " ", SB, "\n")
