// expect: 4:27: a bezier_spline prism needs four points per piece, found 6 points
// POV-Ray: "Prism with Bezier splines must have four points per segment."
#version 3.7;
prism { bezier_spline 0 1 6 <0,0> <1,0> <1,1> <0,0> <2,2> <3,3> }
