// checks 2-component (uv) vectors and their promotion
#version 3.7;
#declare A = <1,2>;
#declare B = <3,4>;
#debug concat(vstr(2, A+B, ",", 0, 6), "\n")
#debug concat(vstr(2, A*B, ",", 0, 6), "\n")
#debug concat(vstr(3, A, ",", 0, 6), "\n")
#debug concat(vstr(2, u, ",", 0, 6), " ", vstr(2, v, ",", 0, 6), "\n")
#debug concat(str(A.u, 0, 6), " ", str(A.v, 0, 6), " ", str(A.x, 0, 6), " ", str(A.y, 0, 6), "\n")
#debug concat(vstr(2, A*3+1, ",", 0, 6), "\n")
