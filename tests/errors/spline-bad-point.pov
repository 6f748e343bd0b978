// expect: 2:40: a spline point needs a number, vector or color, not a string
#declare S = spline { linear_spline 0, "a" }
