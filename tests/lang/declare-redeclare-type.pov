// checks redeclaring an identifier with a value of another type
#version 3.7;
#declare A = 1;
#debug concat(str(A, 0, 6), "\n")
#declare A = "now a string";
#debug concat(A, "\n")
#declare A = <4, 5, 6>;
#debug concat(vstr(3, A, ",", 0, 6), "\n")
#declare A = array[2] {7, 8};
#debug concat(str(A[1], 0, 6), "\n")
#declare A = 9;
#debug concat(str(A, 0, 6), "\n")
