// expect: 2:18: '<' needs numbers, vectors or colors (or two strings), not a string
#declare A = "a" < 2;
