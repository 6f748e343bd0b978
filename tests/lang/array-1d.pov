// checks a 1-D array: uninitialised declaration, element assignment and reading
#version 3.7;
#declare A = array[5];
#for (I, 0, 4) #declare A[I] = I * I; #end
#for (I, 0, 4) #debug concat(str(A[I], 0, 0), " ") #end
#debug "\n"
#declare A[2] = A[2] + 100;
#debug concat(str(A[2], 0, 0), "\n")
