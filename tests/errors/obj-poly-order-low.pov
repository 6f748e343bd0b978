// expect: 2:8: a poly's order must be from 2 to 7, found 1
poly { 1, <1, 2, 3, 4> }
