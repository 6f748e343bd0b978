// expect: 3:15: this matrix cannot be inverted (it flattens space)
// Rank 2: every point lands in a plane.
sphere { 0, 1 matrix <1,0,1, 0,1,1, 1,1,2, 0,0,0> }
