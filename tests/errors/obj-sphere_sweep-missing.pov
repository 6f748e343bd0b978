// Fewer spheres than the count (POV-Ray: "Expected 'numeric expression', } found instead").
// expect: 3:73: expected an expression
sphere_sweep { cubic_spline 4, <0, 0, 0>, 1, <1, 0, 0>, 1, <2, 0, 0>, 1 }
