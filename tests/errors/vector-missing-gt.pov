// expect: 2:16: expected ',' or '>' in vector, found 'sphere'
sphere { <0, 0 sphere { 0, 1 } }
