// checks a function with the default parameters x, y, z
#version 3.7;
#declare F = function { x*y+z }
#debug concat(str(F(2, 3, 4), 0, 6), " ", str(F(0.5, -2, 1), 0, 6), "\n")
#declare Gy = function { y }
#declare S = function { x + y + z }
#debug concat(str(Gy(1, 2, 3), 0, 6), " ", str(S(1, 2, 3), 0, 6), "\n")
