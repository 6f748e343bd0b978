// checks all four spline kinds on unevenly spaced points, inside and outside the range
#version 3.7;
#declare Q = spline { quadratic_spline 0, <0,0,0> 1, <1,3,0> 2.5, <2,1,0> 4, <5,-2,0> 6, <3,3,1> }
#declare C = spline { cubic_spline 0, <0,0,0> 1, <1,3,0> 2.5, <2,1,0> 4, <5,-2,0> 6, <3,3,1> }
#declare N = spline { natural_spline 0, <0,0,0> 1, <1,3,0> 2.5, <2,1,0> 4, <5,-2,0> 6, <3,3,1> }
#declare L = spline { linear_spline 0, <0,0,0> 1, <1,3,0> 2.5, <2,1,0> 4, <5,-2,0> 6, <3,3,1> }
#macro P(V) vstr(3, V + <0,0,0>, ",", 0, 6) #end
#for (T, -0.4, 6.6, 0.25)
#debug concat(str(T,0,3), " ", P(Q(T)), " ", P(C(T)), "\n")
#debug concat("     ", P(N(T)), " ", P(L(T)), "\n")
#end
