// expect: 3:8: expected a string, found a float
#declare A = 1;
#debug A
