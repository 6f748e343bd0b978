// checks an array of vectors and dot items on its elements
#version 3.7;
#declare P = array[3] {<1,2,3>, <4,5,6>, x};
#for (I, 0, 2) #debug concat(vstr(3, P[I], ",", 0, 0), " ") #end
#debug "\n"
#debug concat(str(P[1].y, 0, 0), " ", str(P[0].z + P[2].x, 0, 0), "\n")
#declare P[2] = P[0] + P[1];
#debug concat(vstr(3, P[2], ",", 0, 0), "\n")
