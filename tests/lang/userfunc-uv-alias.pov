// checks that u is the same parameter as x and v the same as y
#version 3.7;
#declare F1 = function(u, v) { x + y * v }
#declare F2 = function(x, v, z) { u + y * v + z }
#debug concat(str(F1(2, 3), 0, 6), " ", str(F2(1, 2, 3), 0, 6), "\n")
