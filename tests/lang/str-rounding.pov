// checks how str() rounds (C printf rounding of the binary value, ties to even)
#version 3.7;
#debug concat("[", str(0.5, 0, 0), "] [", str(1.5, 0, 0), "] [", str(2.5, 0, 0), "] [", str(3.5, 0, 0), "]\n")
#debug concat("[", str(-0.5, 0, 0), "] [", str(-1.5, 0, 0), "] [", str(-2.5, 0, 0), "]\n")
#debug concat("[", str(0.125, 0, 2), "] [", str(0.375, 0, 2), "] [", str(0.625, 0, 2), "]\n")
#debug concat("[", str(99.999, 0, 2), "] [", str(-99.999, 0, 2), "] [", str(9.9999996, 0, 6), "]\n")
#debug concat("[", str(1.005, 0, 2), "] [", str(2.675, 0, 2), "] [", str(0.0005, 0, 3), "]\n")
#debug concat("[", str(0.4999999, 0, 0), "] [", str(1/3, 0, 3), "] [", str(2/3, 0, 3), "]\n")
