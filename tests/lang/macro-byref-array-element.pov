// checks passing an array element to a macro that #declares the parameter
#version 3.7;
#macro Inc(V) #declare V = V + 1; #end
#declare A = array[3] {10, 20, 30};
Inc(A[1])
#debug concat(str(A[0], 0, 0), " ", str(A[1], 0, 0), " ", str(A[2], 0, 0), "\n")
