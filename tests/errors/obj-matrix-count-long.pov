// expect: 2:62: too many entries: at most 12
#declare T = transform { matrix <1,0,0, 0,1,0, 0,0,1, 0,0,0, 1> }
