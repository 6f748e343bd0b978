// checks str() with negative L: minimum width abs(L), padded with zeros after the sign
#version 3.7;
#debug concat("[", str(3.14159, -5, 2), "]\n")
#debug concat("[", str(123.456, -9, 3), "]\n")
#debug concat("[", str(-123.456, -9, 3), "]\n")
#debug concat("[", str(-1.5, -10, 0), "]\n")
#debug concat("[", str(-5, -6, 1), "]\n")
#debug concat("[", str(0, -3, 0), "]\n")
#debug concat("[", str(7, -1, 0), "]\n")
#debug concat("[", str(7, -2, 0), "]\n")
#debug concat("[", str(12345.6789, -12, 2), "]\n")
#debug concat("[", str(42, -4, 0), "]\n")
