// checks min_extent/max_extent of cylinders and cones: POV-Ray's box is the corners of
// [-R,R]^2 x [0,len] (R the larger radius) carried to the axis by the rotation taking z to
// minus the axis, then by the object's transform as one matrix. (Cases whose sides are 0
// print -0.000000 in POV-Ray, from the sines and cosines it builds that rotation with, and
// single-precision 7th digits, are left out.)
#version 3.7;
#macro P(N, O) #debug concat(N, " ", vstr(3, min_extent(O), ",", 0, 6), "  ", vstr(3, max_extent(O), ",", 0, 6), "\n") #end
P("cyl<1,1,0>", cylinder { 0, <1,1,0>, 1 })
P("cone<1,1,0>", cone { <1,0.5,0>, 0.5, <1,1,0>, 1.5 })
P("cyl<1,2.5,1>", cylinder { 0, <1,2.5,1>, 1 })
P("cone<1,2.5,1>", cone { <1,0.5,0>, 0.5, <1,2.5,1>, 1.5 })
P("cyl<0,1,1>", cylinder { 0, <0,1,1>, 1 })
P("cone<0,1,1>", cone { <1,0.5,0>, 0.5, <0,1,1>, 1.5 })
P("cyl<1,0,1>", cylinder { 0, <1,0,1>, 1 })
P("cone<1,0,1>", cone { <1,0.5,0>, 0.5, <1,0,1>, 1.5 })
P("cyl<1,1,1>", cylinder { 0, <1,1,1>, 1 })
P("cone<1,1,1>", cone { <1,0.5,0>, 0.5, <1,1,1>, 1.5 })
P("cyl<2,1,0.5>", cylinder { 0, <2,1,0.5>, 1 })
P("cyl<-1,2,3>", cylinder { 0, <-1,2,3>, 1 })
P("cone<0.3,-1,0.2>", cone { <1,0.5,0>, 0.5, <0.3,-1,0.2>, 1.5 })
P("cyl<1,-1,0>", cylinder { 0, <1,-1,0>, 1 })
P("cone<1,-1,0>", cone { <1,0.5,0>, 0.5, <1,-1,0>, 1.5 })
P("cyl", cylinder { <1,0.5,0>, <2,3,1>, 0.5 })
P("cyl-r", cylinder { <1,0.5,0>, <2,3,1>, 0.5 rotate <20,30,40> })
P("cyl-open", cylinder { <1,0.5,0>, <2,3,1>, 0.5 open translate x })
P("cone", cone { <1,0.5,0>, 1, <2,3,1>, 0.5 })
P("cyl-y", cylinder { 0, 2*y, 0.5 })
P("cyl-x", cylinder { <1,2,3>, <3,2,3>, 0.5 })
P("cone-neg", cone { 0, -1, x+y, 0.5 })
P("cyl-in-union", union { cylinder { 0, <1,1,1>, 0.2 } sphere { 0, 0.1 } })
P("cyl-in-isect", intersection { cylinder { 0, <1,1,1>, 0.2 } box { -1, 0.5 } })
