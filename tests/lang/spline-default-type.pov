// checks that a spline without a type keyword is linear, with optional commas
#version 3.7;
#declare S = spline {
  0, <0, 0, 0>,
  2, <2, 4, 6>,
  4, <0, 0, 0>
}
#declare S2 = spline { 0, <0,0,0> 2, <2,4,6> 4, <0,0,0> }
#for (T, 0, 4, 0.5)
  #debug concat(str(T, 0, 1), ": ", vstr(3, S(T), ",", 0, 6), " ", vstr(3, S2(T), ",", 0, 6), "\n")
#end
