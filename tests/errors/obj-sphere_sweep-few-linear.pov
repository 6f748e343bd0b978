// A linear_spline sweep needs two spheres (POV-Ray: "Too few modeling spheres for interpolation type").
// expect: 3:30: a linear_spline sphere_sweep needs at least 2 spheres, found 1
sphere_sweep { linear_spline 1, <0, 0, 0>, 1 pigment { rgb 1 } }
