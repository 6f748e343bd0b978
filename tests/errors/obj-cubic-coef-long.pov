// expect: 2:52: too many entries: at most 20
cubic { <0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,0,0, 1> }
