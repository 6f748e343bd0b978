// checks str() with large and very small magnitudes
#version 3.7;
#debug concat(str(1e20, 0, 6), "\n")
#debug concat(str(1e-20, 0, 6), "\n")
#debug concat(str(12345678.9, 0, 2), "\n")
#debug concat(str(0.000001234, 0, 10), "\n")
#debug concat(str(-9876543.21, 15, 1), "\n")
#debug concat(str(2147483648, 0, 0), "\n")
