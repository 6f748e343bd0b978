// checks linear_spline at many parameter values, including outside the range
#version 3.7;
#declare S = spline {
  linear_spline
  0, <0, 0, 0>
  1, <1, 2, 0>
  3, <5, 2, -2>
  4, <5, 0, 4>
}
#for (T, -1, 5, 0.25)
  #debug concat(str(T, 5, 2), ": ", vstr(3, S(T), ",", 0, 6), "\n")
#end
