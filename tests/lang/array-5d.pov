// checks a 5-D array (the maximum) with element assignment
#version 3.7;
#declare A = array[2][1][2][1][3];
#declare A[1][0][1][0][2] = 42;
#declare A[0][0][0][0][0] = 7;
#debug concat(str(A[1][0][1][0][2], 0, 0), " ", str(A[0][0][0][0][0], 0, 0), " ", str(dimensions(A), 0, 0), " ", str(dimension_size(A, 5), 0, 0), "\n")
