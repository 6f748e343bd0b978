// expect: 2:23: dimension 1 of the array has size 3, but 2 initialisers were given
#declare A = array[3] { 1, 2 };
