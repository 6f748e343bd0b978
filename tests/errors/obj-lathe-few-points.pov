// A quadratic_spline lathe needs three points (POV-Ray: "Lathe with quadratic splines must have at least three points").
// expect: 3:26: a quadratic_spline lathe needs at least 3 points, found 2
lathe { quadratic_spline 2, <0,0>, <1,0> }
