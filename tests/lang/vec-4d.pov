// checks 4-component vectors, the t axis and promotion of 3D to 4D
#version 3.7;
#declare A = <1,2,3,4>;
#declare B = <10,20,30,40>;
#debug concat(vstr(4, A+B, ",", 0, 6), "\n")
#debug concat(vstr(4, A*2, ",", 0, 6), "\n")
#debug concat(vstr(4, t, ",", 0, 6), "\n")
#debug concat(str(A.x, 0, 6), " ", str(A.y, 0, 6), " ", str(A.z, 0, 6), " ", str(A.t, 0, 6), "\n")
#declare C = A + x;
#debug concat(vstr(4, C, ",", 0, 6), "\n")
#declare D = x + t*2;
#debug concat(vstr(4, D, ",", 0, 6), "\n")
