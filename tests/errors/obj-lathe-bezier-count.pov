// A bezier_spline lathe takes four points per piece (POV-Ray: "Lathe with Bezier splines must have four points per segment").
// expect: 3:23: a bezier_spline lathe needs four points per piece, found 5 points
lathe { bezier_spline 5, <0,0>, <1,0>, <1,1>, <2,2>, <3,3> }
