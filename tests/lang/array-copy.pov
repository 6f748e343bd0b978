// checks that assigning an array copies it (changing the copy leaves the original)
#version 3.7;
#declare A = array[3] {1, 2, 3};
#declare B = A;
#declare B[0] = 100;
#debug concat(str(A[0], 0, 0), " ", str(B[0], 0, 0), "\n")
#declare G = array[2][2] {{1, 2}, {3, 4}};
#declare H = G;
#declare H[1][1] = 40;
#debug concat(str(G[1][1], 0, 0), " ", str(H[1][1], 0, 0), "\n")
