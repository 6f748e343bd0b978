// expect: 4:28: a spline function takes no parameter list
// POV-Ray: "Function parameters for spline functions are not allowed."
#version 3.7;
#declare S = function(a) { spline { linear_spline 0, 1 1, 2 } }
