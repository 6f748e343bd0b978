// checks a spline of 2-D vectors (the result has two components)
#version 3.7;
#declare S = spline { linear_spline 1, <4,5> 3, <5,5> 5, <6,5> }
#for (T, 0, 6)
  #debug concat(str(T, 0, 0), ": ", vstr(2, S(T), ",", 0, 6), " y=", str(S(T).y, 0, 6), "\n")
#end
