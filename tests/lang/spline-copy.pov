// checks declaring a spline from another spline identifier and changing its type
#version 3.7;
#declare A = spline { linear_spline 0, <0,0,0> 1, <1,0,0> 2, <0,1,0> 3, <0,0,1> }
#declare B = spline { A }
#declare C = spline { A cubic_spline }
#for (T, 0, 3, 0.5)
  #debug concat(str(T, 0, 1), ": ", vstr(3, B(T), ",", 0, 4), " | ", vstr(3, C(T), ",", 0, 4), "\n")
#end
