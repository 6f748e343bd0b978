// checks abs() on positive, negative, zero and expression arguments
#version 3.7;
#debug concat(str(abs(3.5), 0, 6), " ", str(abs(-3.5), 0, 6), " ", str(abs(0), 0, 6), " ", str(abs(-1e-7), 0, 9), " ", str(abs(2-5), 0, 6), "\n")
