// expect: 2:15: a matrix needs exactly 12 numbers
sphere { 0, 1 matrix <1, 0, 0, 0, 1, 0> }
