// checks a spline wrapped in a function { spline { ... } } and called like a vector function
#version 3.7;
#declare foo2 = function {
  spline {
    linear_spline
    0.0, <0,0,0>
    0.5, <1,0,0>
    1.0, <0,0,0>
  }
}
#declare myvector2 = foo2(0.7);
#debug concat(vstr(3, myvector2, ",", 0, 6), "\n")
#debug concat(vstr(3, foo2(0.25), ",", 0, 6), "\n")
