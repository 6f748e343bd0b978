// checks that every spline type returns an end point for parameters far outside the range
#version 3.7;
#declare L = spline { linear_spline 0, <1,1,1> 1, <2,3,4> 2, <5,5,5> }
#declare Q = spline { quadratic_spline 0, <1,1,1> 1, <2,3,4> 2, <5,5,5> }
#declare N = spline { natural_spline 0, <1,1,1> 1, <2,3,4> 2, <5,5,5> }
#declare C = spline { cubic_spline 0, <1,1,1> 1, <2,3,4> 2, <5,5,5> 3, <9,9,9> }
#for (T, -100, 100, 50)
  #debug concat(str(T, 0, 0), ": ", vstr(3, L(T), ",", 0, 3), " ", vstr(3, Q(T), ",", 0, 3), " ", vstr(3, N(T), ",", 0, 3), " ", vstr(3, C(T), ",", 0, 3), "\n")
#end
