// expect: 2:15: this matrix cannot be inverted (it flattens space)
sphere { 0, 1 matrix <1,0,0, 0,0,0, 0,0,1, 0,0,0> }
