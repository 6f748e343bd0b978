// checks inside() on a sphere, a box and a CSG difference
#version 3.7;
#declare S = sphere { 0, 1 }
#declare B = box { <-1,-1,-1>, <1,1,1> }
#declare D = difference { box { -2, 2 } sphere { 0, 1 } }
#debug concat(str(inside(S, <0,0,0>), 0, 0), str(inside(S, <0.5,0.5,0.5>), 0, 0), str(inside(S, <1,1,1>), 0, 0), "\n")
#debug concat(str(inside(B, <0.9,-0.9,0>), 0, 0), str(inside(B, <1.5,0,0>), 0, 0), "\n")
#debug concat(str(inside(D, <0,0,0>), 0, 0), str(inside(D, <1.5,1.5,1.5>), 0, 0), str(inside(D, <3,0,0>), 0, 0), "\n")
