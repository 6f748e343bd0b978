// checks a function with many parameters and argument order
#version 3.7;
#declare F = function(a, b, c, d, e, f, g, h, i, j) { a - b + c - d + e - f + g - h + i - j + 1000 * a + 0.001 * j }
#debug concat(str(F(1, 2, 3, 4, 5, 6, 7, 8, 9, 10), 0, 6), "\n")
