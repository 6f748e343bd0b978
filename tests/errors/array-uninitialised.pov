// expect: 3:14: element of array 'A' used before it was given a value
#declare A = array[3];
#declare B = A[1];
