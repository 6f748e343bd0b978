// expect: 2:24: a comparison compares floats, not a vector with a float
#declare A = <1, 2, 3> < 2;
