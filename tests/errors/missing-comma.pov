// expect: 3:16: expected ',' or '>' in vector, found '}'
// Commas between a vector's components may be left out, but the vector must be closed.
sphere { <0, 0 }, 1 }
