// The interpolation comes first (POV-Ray: "Invalid type of interpolation").
// expect: 3:16: expected linear_spline, b_spline or cubic_spline
sphere_sweep { 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }
