// checks function { spline { } } for splines of floats, 2-, 4- and
// 5-component vectors, a declared spline, each spline type, and a
// transform function made from a declared transform and an inverse
#version 3.7;
#declare SF = function { spline { linear_spline 0, 1 1, 3 } }
#declare S2 = function { spline { linear_spline 0, <1,2> 1, <3,4> } }
#declare S4 = function { spline { quadratic_spline 0, <1,2,3,4> 1, <3,4,5,6> 2, <0,1,0,1> } }
#declare S5 = function { spline { natural_spline 0, <1,2,3,4,5> 1, <3,4,5,6,7> 2, <0,0,0,0,0> 3, <1,1,1,1,1> } }
#declare SP = spline { cubic_spline -1, <0,0,0> 0, <1,2,3> 1, <3,4,5> 2, <0,0,0> }
#declare SC = function { spline { SP } }
#declare SL = function { spline { SP linear_spline } }
#debug concat(vstr(5, SF(0.5), ",", 0, 6), "\n")
#debug concat(vstr(5, S2(0.25), ",", 0, 6), "\n")
#debug concat(vstr(4, S4(1.5), ",", 0, 6), "\n")
#debug concat(vstr(5, S5(1.5), ",", 0, 6), "\n")
#debug concat(vstr(3, SC(0.5), ",", 0, 6), "\n")
#debug concat(vstr(3, SL(0.5), ",", 0, 6), "\n")
#debug concat(vstr(3, SC(-5), ",", 0, 6), "\n")
#debug concat(vstr(3, SC(7), ",", 0, 6), "\n")
#declare TR = transform { rotate <0, 90, 0> translate <0, 1, 0> }
#declare T1 = function { transform { TR } }
#declare T2 = function { transform { TR inverse } }
#declare P = T1(1, 2, 3);
#debug concat(vstr(3, P, ",", 0, 6), "\n")
#debug concat(vstr(3, T2(P.x, P.y, P.z), ",", 0, 6), "\n")
#declare Q = T1(1, 0, 0) + SC(0.5) * 2;
#debug concat(vstr(3, Q, ",", 0, 6), "\n")
