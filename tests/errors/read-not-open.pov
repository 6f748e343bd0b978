// expect: 3:8: the file 'Nope' is not open (or was read to its end)
#declare V = 0;
#read (Nope, V)
