// expect: 3:3: a cubic of order 3 needs 20 coefficients, found 19
cubic {
  <0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,0,0,1>
}
