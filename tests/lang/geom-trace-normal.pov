// checks trace() normals: the outward normal of the leaf, turned over for each inverse
// object above it (and for a difference's subtracted objects), never toward the ray
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#macro T(N, O, A, D) #local Nr = <0,0,0>; #local P = trace(O, A, D, Nr); #debug concat(N, " ", V3(P), "  n ", V3(Nr), "\n") #end
T("plane-above", plane { y, 0 }, <0,1,0>, <0,-1,0>)
T("plane-below", plane { y, 0 }, <0,-1,0>, <0,1,0>)
T("disc-above", disc { 0, y, 1 }, <0,1,0>, <0,-1,0>)
T("disc-below", disc { 0, y, 1 }, <0,-1,0>, <0,1,0>)
T("tri-above", triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> }, <0,1,0>, <0,-1,0>)
T("tri-below", triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> }, <0,-1,0>, <0,1,0>)
T("stri-below", smooth_triangle { <-1,0,-1>, y, <1,0,-1>, y, <0,0,1>, y }, <0,-1,0>, <0,1,0>)
T("mesh-below", mesh { triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> } }, <0,-1,0>, <0,1,0>)
T("mesh-above", mesh { triangle { <-1,0,-1>, <1,0,-1>, <0,0,1> } }, <0,1,0>, <0,-1,0>)
T("sphere-in", sphere { 0, 2 }, <0,0,0>, <0,1,0>)
T("box-in", box { -1, 1 }, <0,0,0>, <0,1,0>)
T("plane-inv-above", plane { y, 0 inverse }, <0,1,0>, <0,-1,0>)
T("disc-rot", disc { 0, y, 1 rotate 180*x }, <0,1,0>, <0,-1,0>)
T("cyl-open-in", cylinder { -y, y, 1 open }, <0,0,0>, <1,0,0>)
T("tri-rev", triangle { <0,0,1>, <1,0,-1>, <-1,0,-1> }, <0,1,0>, <0,-1,0>)
T("tri-xy", triangle { <0,0,0>, <1,0,0>, <0,1,0> }, <0.2,0.2,-1>, <0,0,1>)
T("mesh-rev", mesh { triangle { <0,0,1>, <1,0,-1>, <-1,0,-1> } }, <0,1,0>, <0,-1,0>)
T("sph-inv", sphere { 0, 2 inverse }, <0,0,0>, <0,1,0>)
T("sph-inv-out", sphere { 0, 2 inverse }, <0,5,0>, <0,-1,0>)
T("diff", difference { box{-1,1} sphere{<0,1,0>,0.5} }, <0,2,0>, <0,-1,0>)
T("isect-inv", intersection { box{-1,1} sphere{<0,1,0>,0.5} inverse }, <0,2,0>, <0,-1,0>)
T("box-inv", box { -1, 1 inverse }, <0,2,0>, <0,-1,0>)
T("stri-rev", smooth_triangle { <0,0,1>, y, <1,0,-1>, y, <-1,0,-1>, y }, <0,1,0>, <0,-1,0>)
T("stri-neg", smooth_triangle { <0,0,1>, -y, <1,0,-1>, -y, <-1,0,-1>, -y }, <0,1,0>, <0,-1,0>)
T("disc-inv", disc { 0, y, 1 inverse }, <0,1,0>, <0,-1,0>)
T("sph-scaled", sphere { 0, 1 scale <1,2,1> }, <0,3,0>, <0,-1,0>)
