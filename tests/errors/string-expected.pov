// expect: 3:8: expected a string, but 'A' is a float
#declare A = 1;
#debug A
