// expect: 2:15: expected an object modifier or '}', found 'radius'
sphere { 0, 1 radius 2 }
