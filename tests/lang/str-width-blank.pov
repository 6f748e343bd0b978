// checks str() with positive L: minimum width, padded on the left with blanks
#version 3.7;
#debug concat("[", str(123.456, 4, 3), "]\n")
#debug concat("[", str(123.456, 9, 3), "]\n")
#debug concat("[", str(123.456, 5, 0), "]\n")
#debug concat("[", str(123.000, 7, 2), "]\n")
#debug concat("[", str(-1.5, 10, 0), "]\n")
#debug concat("[", str(-5, 6, 1), "]\n")
#debug concat("[", str(7, 1, 0), "]\n")
#debug concat("[", str(7, 2, 0), "]\n")
#debug concat("[", str(0.25, 12, 4), "]\n")
