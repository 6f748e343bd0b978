// checks inside() on a box's faces, edges and corners: POV-Ray 3.7 counts them as inside
// (also transformed), and a CSG made of boxes that meet along faces keeps those points.
// (A box flat along an axis is left out: POV-Ray gives it an inside, lucent none; see
// tests/stability/degenerate.pov.)
#version 3.7;
#declare B = box { -1, 1 }
#declare R = box { -1, 1 rotate 90*y }
#declare T = box { -1, 1 translate 0.1 }
#declare S = box { -1, 1 scale 0.3 }
#declare I = intersection { box { <-1,-1,-1>, <1,1,0> } box { <-1,-1,0>, <1,1,1> } }
#declare U = union { box { <-1,-1,-1>, <0,1,1> } box { <0,-1,-1>, <1,1,1> } }
#declare D = difference { box { -1, 1 } box { <0,-2,-2>, <2,2,2> } }
#macro P(N, O, V) #debug concat(N, " ", vstr(3, V, ",", 0, 3), " ", str(inside(O, V), 0, 0), "\n") #end
P("B", B, <1,0,0>) P("B", B, <1,1,1>) P("B", B, <-1,-1,0.5>) P("B", B, <1.0000001,0,0>) P("B", B, <0,-1.0000001,0>)
P("R", R, <1,0,0>) P("R", R, <0,0,-1>)
P("T", T, <1.1,0,0>) P("T", T, <-0.9,-0.9,-0.9>)
P("S", S, <0.3,0,0>) P("S", S, <0.3,0.3,-0.3>)
P("I", I, <0,0,0>) P("I", I, <0.5,0.5,0>) P("I", I, <0.5,0.5,0.001>)
P("U", U, <0,0,0>) P("U", U, <1,1,1>)
P("D", D, <0,0,0>) P("D", D, <-0.5,0,0>) P("D", D, <-1,0,0>)
