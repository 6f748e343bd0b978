// checks functions with explicit parameter lists of various lengths
#version 3.7;
#declare foo2 = function(x, y, z) { x + y * z }
#declare foo3 = function(k1, k2, z, y) { x + y * z + k1 * y + k2 }
#declare foo4 = function(h) { h * h + h }
#debug concat(str(foo2(1, 2, 3), 0, 6), " ", str(foo3(1, 2, 3, 4), 0, 6), " ", str(foo4(3), 0, 6), "\n")
#declare Five = function(a, b, c, d, e) { a + 2*b + 3*c + 4*d + 5*e }
#debug concat(str(Five(1, 1, 1, 1, 1), 0, 6), " ", str(Five(5, 4, 3, 2, 1), 0, 6), "\n")
