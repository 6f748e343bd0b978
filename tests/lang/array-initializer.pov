// checks 1-D array initialisers with floats, expressions and identifiers
#version 3.7;
#declare K = 10;
#declare A = array[4] {1, 2.5, K*2, -K};
#for (I, 0, 3) #debug concat(str(A[I], 0, 2), " ") #end
#debug "\n"
#debug concat(str(dimension_size(A, 1), 0, 0), "\n")
