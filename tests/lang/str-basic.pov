// checks str() with L = 0 and various precisions P
#version 3.7;
#debug concat("[", str(123.456, 0, 3), "]\n")
#debug concat("[", str(123.456, 0, 2), "]\n")
#debug concat("[", str(123.456, 0, 0), "]\n")
#debug concat("[", str(123.456, 0, 1), "]\n")
#debug concat("[", str(-123.456, 0, 3), "]\n")
#debug concat("[", str(0, 0, 3), "]\n")
#debug concat("[", str(1234567, 0, 0), "]\n")
#debug concat("[", str(1e15, 0, 0), "]\n")
