// expect: 2:20: an array dimension must be from 1 to 100000000, not 0
#declare A = array[0];
