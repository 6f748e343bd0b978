// expect: 2:19: '<' needs numbers, vectors or colors (or two strings), not a string
#declare A = ("a" < 2);
