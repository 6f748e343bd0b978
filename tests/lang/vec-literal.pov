// checks 3-component vector literals with expression components
#version 3.7;
#declare This = 2;
#declare That = 9;
#declare V = <This+3, That/3, 5*This>;
#debug concat(vstr(3, V, ", ", 0, 6), "\n")
#debug concat(vstr(3, < 1.0, 3.2, -5.4578 >, ", ", 0, 6), "\n")
#debug concat(vstr(3, <-1,-2,-3>, ", ", 0, 6), "\n")
#debug concat(vstr(3, <1, 3.2-5.4578, 2>, ", ", 0, 6), "\n")
