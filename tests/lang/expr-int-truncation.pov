// checks that integer contexts truncate floats (array index, str precision, chr)
#version 3.7;
#declare A = array[3] {10, 20, 30};
#debug concat(str(A[1.9], 0, 6), " ", str(A[0.2], 0, 6), " ", str(A[2.999], 0, 6), "\n")
#debug concat(str(3.14159, 0, 2.9), "\n")
#debug concat(chr(65.7), "\n")
#debug concat(substr("ABCDEF", 2.8, 2.9), "\n")
