// checks writing a string, a float and a vector with #write and reading them back with #read
#version 3.7;
#declare Val1 = -123.45;
#declare Vect1 = <1,2,-3>;
#fopen F "fileio-write-read.tmp" write
#write (F, "\"A quote delimited string\",", Val1, ",", Vect1, "\n")
#fclose F
#fopen G "fileio-write-read.tmp" read
#read (G, MyString, MyFloat, MyVect)
#fclose G
#debug concat(MyString, "\n")
#debug concat(str(MyFloat, 0, 6), "\n")
#debug concat(vstr(3, MyVect, ",", 0, 6), "\n")
