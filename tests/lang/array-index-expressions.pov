// checks array indices computed from expressions, truncated to integers
#version 3.7;
#declare A = array[10] {0, 10, 20, 30, 40, 50, 60, 70, 80, 90};
#declare I = 3;
#debug concat(str(A[I], 0, 0), " ", str(A[I * 2 + 1], 0, 0), " ", str(A[9 - I], 0, 0), "\n")
#debug concat(str(A[sqrt(16)], 0, 0), " ", str(A[2.7], 0, 0), " ", str(A[A[1] / 10], 0, 0), "\n")
