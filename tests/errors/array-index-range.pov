// expect: 3:16: index 3 is out of range for dimension 1 of array 'A' (size 3)
#declare A = array[3] { 1, 2, 3 };
#declare B = A[3];
