// expect: 2:10: a vector needs at least 2 components
sphere { <1>, 1 }
