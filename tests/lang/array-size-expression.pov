// checks array sizes given as expressions (truncated) and dimension_size results
#version 3.7;
#declare N = 3;
#declare A = array[N * 2][N + 0.9];
#debug concat(str(dimension_size(A, 1), 0, 0), " ", str(dimension_size(A, 2), 0, 0), "\n")
