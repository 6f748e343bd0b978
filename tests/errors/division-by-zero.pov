// expect: 2:16: division by zero
#declare A = 1 / 0;
