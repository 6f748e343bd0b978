// expect: 2:11: a poly of order 2 needs 10 coefficients, found 9
poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0> }
