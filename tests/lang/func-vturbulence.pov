// checks vturbulence at a few points with a few parameter sets
#version 3.7;
#debug concat(vstr(3, vturbulence(2, 0.5, 6, <0.5, 0.25, 0.125>), ",", 0, 6), "\n")
#debug concat(vstr(3, vturbulence(2, 0.5, 1, <1.3, 2.7, -0.4>), ",", 0, 6), "\n")
#debug concat(vstr(3, vturbulence(3, 0.25, 3, <10.1, -5.2, 3.3>), ",", 0, 6), "\n")
