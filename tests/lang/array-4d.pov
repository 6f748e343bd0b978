// checks a 4-D array with a nested initialiser
#version 3.7;
#declare A = array[2][2][2][2] {
  { { {0, 1}, {2, 3} }, { {4, 5}, {6, 7} } },
  { { {8, 9}, {10, 11} }, { {12, 13}, {14, 15} } }
}
#debug concat(str(A[0][0][0][0], 0, 0), " ", str(A[0][1][1][0], 0, 0), " ", str(A[1][0][1][1], 0, 0), " ", str(A[1][1][1][1], 0, 0), "\n")
#debug concat(str(dimensions(A), 0, 0), "\n")
