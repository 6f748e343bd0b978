// expect: 3:12: index 5 is out of range for dimension 1 of array 'A' (size 2)
#declare A = array[2];
#declare A[5] = 1;
