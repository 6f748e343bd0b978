// checks str() with negative P: the default precision (six digits)
#version 3.7;
#debug concat("[", str(5, 0, -1), "]\n")
#debug concat("[", str(5, 0, -5), "]\n")
#debug concat("[", str(123.456, 0, -1), "]\n")
#debug concat("[", str(-5, -8, -1), "]\n")
#debug concat("[", str(3.14159, -10, -1), "]\n")
#debug concat("[", str(1e-7, 0, -1), "]\n")
#debug concat("[", str(2/3, 12, -3), "]\n")
