// expect: 2:13: expected a float, found a vector
sphere { 0, <1, 2, 3> }
