// expect: 2:31: too many initialisers for dimension 1 of the array (its size is 2)
#declare A = array[2] { 1, 2, 3 };
