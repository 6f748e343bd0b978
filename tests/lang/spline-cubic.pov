// checks cubic_spline (first and last points are control points) at many values
#version 3.7;
#declare MySpline =
spline {
  cubic_spline
    -.25, <0,0,-1>
    0.00, <1,0,0>
    0.25, <0,0,1>
    0.50, <-1,0,0>
    0.75, <0,0,-1>
    1.00, <1,0,0>
    1.25, <0,0,1>
}
#for (T, -0.5, 1.5, 0.125)
  #debug concat(str(T, 6, 3), ": ", vstr(3, MySpline(T), ",", 0, 6), "\n")
#end
