// checks component-wise vector addition and subtraction
#version 3.7;
#declare A = <1,2,3>;
#declare B = <4,5,6>;
#debug concat(vstr(3, A+B, ",", 0, 6), "\n")
#debug concat(vstr(3, B-A, ",", 0, 6), "\n")
#debug concat(vstr(3, A-B-A, ",", 0, 6), "\n")
#debug concat(vstr(3, -A, ",", 0, 6), "\n")
#debug concat(vstr(3, +A, ",", 0, 6), "\n")
#debug concat(vstr(3, -A+B, ",", 0, 6), "\n")
