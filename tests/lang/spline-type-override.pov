// checks evaluating a spline as another type: S(T, type)
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 4), ",", str(R6(V.y), 0, 4), ",", str(R6(V.z), 0, 4)) #end
#declare S = spline {
  cubic_spline
  0, <0, 0, 0>
  1, <1, 1, 0>
  2, <2, 0, 0>
  3, <3, 1, 0>
  4, <4, 0, 0>
}
#for (T, 1, 3, 0.5)
  #debug concat(str(T, 0, 1), " as is:     ", V3(S(T)), "\n")
  #debug concat(str(T, 0, 1), " linear:    ", V3(S(T, linear_spline)), "\n")
  #debug concat(str(T, 0, 1), " quadratic: ", V3(S(T, quadratic_spline)), "\n")
  #debug concat(str(T, 0, 1), " natural:   ", V3(S(T, natural_spline)), "\n")
  #debug concat(str(T, 0, 1), " cubic:     ", V3(S(T, cubic_spline)), "\n")
#end
