// b_spline and cubic_spline need four spheres; the count is truncated (POV-Ray: "Too few modeling spheres").
// expect: 3:25: a b_spline sphere_sweep needs at least 4 spheres, found 3
sphere_sweep { b_spline 3.9, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1, <3, 0, 0>, 1 }
