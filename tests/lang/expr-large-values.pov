// checks arithmetic with large and small magnitudes
#version 3.7;
#debug concat(str(1e15 + 1, 0, 0), "\n")
#debug concat(str(1e16 + 1, 0, 0), "\n")
#debug concat(str(1e-300 * 1e300, 0, 6), "\n")
#debug concat(str(123456789 * 1000, 0, 0), "\n")
#debug concat(str(2147483647 + 1, 0, 0), "\n")
#debug concat(str(-1e10 / 3, 0, 3), "\n")
