// checks that spline points may be given out of order, and a repeated parameter replaces the earlier point
#version 3.7;
#declare S = spline {
  linear_spline
  2, <20, 0, 0>
  0, <0, 0, 0>
  1, <10, 0, 0>
  1, <5, 5, 5>
}
#for (T, 0, 2, 0.5)
  #debug concat(str(T, 0, 1), ": ", vstr(3, S(T), ",", 0, 6), "\n")
#end
