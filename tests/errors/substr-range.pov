// expect: 2:14: substr("abc", 2, 5) reaches past the end of the string (length 3)
#declare S = substr("abc", 2, 5);
