// expect: 2:26: a matrix needs exactly 12 numbers, found 11
#declare T = transform { matrix <1,0,0, 0,1,0, 0,0,1, 0,0> }
