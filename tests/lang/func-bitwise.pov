// checks bitwise_and bitwise_or bitwise_xor with two and more arguments
#version 3.7;
#debug concat(str(bitwise_and(12, 10), 0, 0), " ", str(bitwise_or(12, 10), 0, 0), " ", str(bitwise_xor(12, 10), 0, 0), "\n")
#debug concat(str(bitwise_and(255, 15, 6), 0, 0), " ", str(bitwise_or(1, 2, 4, 8), 0, 0), " ", str(bitwise_xor(7, 1, 2), 0, 0), "\n")
#debug concat(str(bitwise_and(12.9, 10.9), 0, 0), " ", str(bitwise_or(0, 0), 0, 0), " ", str(bitwise_xor(5, 5), 0, 0), "\n")
#debug concat(str(bitwise_and(65535, 4096), 0, 0), " ", str(bitwise_or(65536, 1), 0, 0), "\n")
