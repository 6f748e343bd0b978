// checks a dot item after a spline evaluation
#version 3.7;
#declare S = spline { linear_spline 0, <0,0,0>, 1, <10,20,30> }
#debug concat(str(S(0.5).x, 0, 6), " ", str(S(0.5).y, 0, 6), " ", str(S(0.25).z, 0, 6), "\n")
