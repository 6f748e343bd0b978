// checks vector literals whose components come from dot items of other vectors
#version 3.7;
#declare A = <1,2,3>;
#declare B = <A.z, A.y, A.x>;
#debug concat(vstr(3, B, ",", 0, 6), "\n")
#declare C = <A.x*2, (A.y+A.z)/5, -A.x>;
#debug concat(vstr(3, C, ",", 0, 6), "\n")
#declare D = <vlength(<3,4,0>), vdot(A,A), 1>;
#debug concat(vstr(3, D, ",", 0, 6), "\n")
