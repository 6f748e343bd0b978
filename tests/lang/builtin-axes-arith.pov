// checks the built-in axis vectors used as scale factors and in dot products
#version 3.7;
#debug concat(str(vdot(x, y), 0, 6), " ", str(vdot(x, x), 0, 6), "\n")
#debug concat(vstr(3, 3*x + 4*y + 5*z, ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(y, z), ",", 0, 6), "\n")
#debug concat(vstr(3, vcross(z, y), ",", 0, 6), "\n")
#debug concat(vstr(2, u*2 + v*3, ",", 0, 6), "\n")
