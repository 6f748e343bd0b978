// expect: 4:29: a linear_spline prism needs at least 3 points, found 2
// POV-Ray: "Prism with linear splines must have at least three points."
#version 3.7;
prism { linear_spline 0, 1, 2, <0,0>, <1,0> }
