// checks dimension_size with a dimension far outside int's range: 0, as
// POV-Ray 3.7 prints "0 0 4" (its int cast of 1e30 is the smallest int); the
// cast was undefined behaviour in lucent (the same class as a fuzzing find)
#version 3.7;
#declare A = array[3][4];
#debug concat(str(dimension_size(A, 1e30),0,0), " ", str(dimension_size(A, -1e30),0,0), " ", str(dimension_size(A, 2),0,0), "\n")
