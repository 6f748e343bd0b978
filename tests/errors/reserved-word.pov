// expect: 2:10: 'sphere' is a reserved word and cannot be declared
#declare sphere = 1;
