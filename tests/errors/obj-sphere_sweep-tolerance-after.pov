// tolerance comes straight after the spheres, not among the modifiers (POV-Ray: "No matching } in 'sphere_sweep', tolerance found instead").
// expect: 3:78: expected an object modifier or '}', found 'tolerance'
sphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 pigment { rgb 1 } tolerance 0.1 }
