// checks the built-in vectors x y z t u v
#version 3.7;
#debug concat("x=", vstr(3, x, ",", 0, 6), "\n")
#debug concat("y=", vstr(3, y, ",", 0, 6), "\n")
#debug concat("z=", vstr(3, z, ",", 0, 6), "\n")
#debug concat("t=", vstr(4, t, ",", 0, 6), "\n")
#debug concat("u=", vstr(2, u, ",", 0, 6), "\n")
#debug concat("v=", vstr(2, v, ",", 0, 6), "\n")
#debug concat("5*x=", vstr(3, 5*x, ",", 0, 6), "\n")
#debug concat("x+y+z=", vstr(3, x+y+z, ",", 0, 6), "\n")
#debug concat("2*x-3*z=", vstr(3, 2*x-3*z, ",", 0, 6), "\n")
