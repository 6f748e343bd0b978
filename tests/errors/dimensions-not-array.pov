// expect: 3:25: dimensions needs an array, not a float
#declare A = 1;
#declare D = dimensions(A);
