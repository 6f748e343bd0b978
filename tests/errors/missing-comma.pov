// expect: 3:16: expected ',' or '>' in vector, found number 0
// POV-Ray's object arguments need no commas, but a vector's do.
sphere { <0, 0 0>, 1 }
