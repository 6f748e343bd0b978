// checks str() of negative zero and of tiny negative values
#version 3.7;
#debug concat("[", str(-0, 0, 2), "]\n")
#debug concat("[", str(-0.0001, 0, 2), "]\n")
#debug concat("[", str(-1e-9, 0, 6), "]\n")
#debug concat("[", str(0*-1, 0, 1), "]\n")
#debug concat("[", str(ceil(-0.1), 0, 1), "]\n")
