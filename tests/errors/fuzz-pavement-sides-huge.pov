// expect: 4:49: number_of_sides must be 3, 4 or 6, not -2147483648
// Out of int range, the value is POV-Ray's int cast of it (x86: the smallest
// int), not an undefined cast; POV-Ray refuses 1e30 here too.
plane { y, 0 pigment { pavement number_of_sides 1e30 } }
