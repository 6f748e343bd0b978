// checks the smallest splines: two points (linear, quadratic) and four points (cubic)
#version 3.7;
#declare L = spline { linear_spline 0, <0,0,0> 10, <10,20,30> }
#declare Q = spline { quadratic_spline 0, <0,0,0> 10, <10,20,30> }
#declare N = spline { natural_spline 0, <0,0,0> 10, <10,20,30> }
#declare C = spline { cubic_spline -1, <0,0,0> 0, <1,1,1> 1, <2,0,2> 2, <3,3,3> }
#for (T, -1, 11, 3)
  #debug concat(str(T, 0, 0), ": ", vstr(3, L(T), ",", 0, 4), " | ", vstr(3, Q(T), ",", 0, 4), " | ", vstr(3, N(T), ",", 0, 4), "\n")
#end
#for (T, -1.5, 2.5, 0.5)
  #debug concat(str(T, 0, 1), ": ", vstr(3, C(T), ",", 0, 4), "\n")
#end
