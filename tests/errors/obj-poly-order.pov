// expect: 2:8: a poly's order must be from 2 to 7, found 8
poly { 8, <1, 2, 3> }
