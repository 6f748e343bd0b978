// checks a spline whose points have different sizes (the largest decides the result size)
#version 3.7;
#declare S = spline {
  linear_spline
  0, <1, 2>
  1, <3, 4, 5>
  2, <0, 0, 0, 8>
}
#for (T, 0, 2, 0.5)
  #debug concat(str(T, 0, 1), ": ", vstr(4, S(T), ",", 0, 4), "\n")
#end
