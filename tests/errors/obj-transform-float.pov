// expect: 3:25: 'T' is a float, not a transform
#declare T = 5;
sphere { 0, 1 transform T }
