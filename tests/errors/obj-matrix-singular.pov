// expect: 3:26: this matrix cannot be inverted (it flattens space)
// The columns are not zero, but two are equal: POV-Ray stops too ("Singular matrix").
#declare T = transform { matrix <1,1,0, 1,1,0, 0,0,1, 0,0,0> }
