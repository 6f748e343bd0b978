// checks a spline of 5-component vectors (colour-like values)
#version 3.7;
#declare S = spline {
  linear_spline
  0, <1, 0, 0, 0, 0>
  1, <0, 1, 0, 0.5, 0>
  2, <0, 0, 1, 0, 1>
}
#for (T, 0, 2, 0.25)
  #debug concat(str(T, 0, 2), ": ", vstr(5, S(T), ",", 0, 4), "\n")
#end
