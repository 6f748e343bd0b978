// checks that str() truncates fractional L and P to integers
#version 3.7;
#debug concat("[", str(3.14159, 6.9, 2.9), "]\n")
#debug concat("[", str(3.14159, -6.9, 1.2), "]\n")
#debug concat("[", str(3.14159, 0.5, 0.5), "]\n")
