// checks str() with large precision (exact decimal expansion of the double)
#version 3.7;
#debug concat(str(1, 0, 20), "\n")
#debug concat(str(1/3, 0, 20), "\n")
#debug concat(str(0.1, 0, 20), "\n")
#debug concat(str(pi, 0, 16), "\n")
#debug concat(str(1e-10, 0, 12), "\n")
