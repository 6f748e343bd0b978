// checks quadratic_spline at many parameter values, including outside the range
#version 3.7;
#declare S = spline {
  quadratic_spline
  0, <0, 0, 0>
  1, <1, 1, 0>
  2, <2, 0, 1>
  3, <3, 2, -1>
  4, <4, 0, 0>
}
#for (T, -0.5, 4.5, 0.25)
  #debug concat(str(T, 5, 2), ": ", vstr(3, S(T), ",", 0, 6), "\n")
#end
