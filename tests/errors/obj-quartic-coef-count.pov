// expect: 2:11: a quartic of order 4 needs 35 coefficients, found 3
quartic { <1, 0, 0> }
