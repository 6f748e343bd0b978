// checks an array of strings
#version 3.7;
#declare Names = array[3] {"alpha", "beta", "gamma"};
#for (I, 0, 2) #debug concat(str(I, 0, 0), ":", Names[I], " ") #end
#debug "\n"
#declare Names[1] = strupr(Names[1]);
#debug concat(Names[1], " ", str(strlen(Names[2]), 0, 0), "\n")
