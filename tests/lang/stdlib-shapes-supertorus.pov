// stdlib-shapes-supertorus.pov: shapes.inc's Supertorus (an isosurface)
// through its extents, trace() hits with their normals, and inside().
#version 3.7;
#include "shapes.inc"
#macro T(O, Pt, D) #local N = <0,0,0>; #local H = trace(O, Pt, D, N); #debug concat(vstr(3, H, ",", 0, 6), " ", vstr(3, N, ",", 0, 4), "\n") #end
#macro E(O) #debug concat(vstr(3, min_extent(O), ",", 0, 6), " / ", vstr(3, max_extent(O), ",", 0, 6), "\n") #end
#declare S = Supertorus(1, 0.25, 1, 1, 0.001, 1.5)
E(S)
T(S, <0,0,-10>, z)
T(S, <0,10,-1>, -y)
T(S, <0.3,10,-1.1>, -y)
#debug concat(str(inside(S, <1, 0, 0>), 0, 0), str(inside(S, <0, 0, 0>), 0, 0), "\n")
#declare S = Supertorus(1, 0.25, 0.5, 0.3, 0.001, 3)
E(S)
T(S, <0,0,-10>, z)
T(S, <0.3,10,-1.1>, -y)
T(S, <0.3,0.1,-10>, z)
T(S, <0.71,10,-0.71>, -y)
T(S, <0.75,0.1,-10>, z)
#declare S = Supertorus(2, 0.5, 0.2, 0.5, 0.001, 4)
E(S)
T(S, <0,0,-10>, z)
T(S, <0.3,10,-2.1>, -y)
T(S, <1.9,10,-1.9>, -y)
