// checks 5-component vectors and their arithmetic
#version 3.7;
#declare A = <1,2,3,4,5>;
#declare B = <5,4,3,2,1>;
#debug concat(vstr(5, A+B, ",", 0, 6), "\n")
#debug concat(vstr(5, A*B, ",", 0, 6), "\n")
#debug concat(vstr(5, A-1, ",", 0, 6), "\n")
#declare C = A + <1,1>;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = <1,1> + A;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
