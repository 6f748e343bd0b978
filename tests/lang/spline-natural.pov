// checks natural_spline at many parameter values, including outside the range
#version 3.7;
#declare S = spline {
  natural_spline
  0, <0, 0, 0>
  1, <1, 3, 0>
  2, <3, 1, 1>
  4, <4, 4, -2>
  5, <6, 0, 0>
}
#for (T, -1, 6, 0.25)
  #debug concat(str(T, 5, 2), ": ", vstr(3, S(T), ",", 0, 6), "\n")
#end
