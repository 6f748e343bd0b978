// checks that floats mixed with vectors are promoted to all components
#version 3.7;
#debug concat(vstr(3, <1,2,3>-4, ",", 0, 6), "\n")
#debug concat(vstr(3, 4-<1,2,3>, ",", 0, 6), "\n")
#debug concat(vstr(3, <1,2,3>+0.5, ",", 0, 6), "\n")
#declare V = <1,1,1>*0 + 7;
#debug concat(vstr(3, V, ",", 0, 6), "\n")
#declare W = 3 + <0,0,0>;
#debug concat(vstr(3, W, ",", 0, 6), "\n")
#declare P = 5*x + 2;
#debug concat(vstr(3, P, ",", 0, 6), "\n")
