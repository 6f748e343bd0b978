// builtin-trace-csg-normal.pov: trace() on CSG returns the normal of the
// primitive hit (a union, a difference and an intersection), not a
// constant. (Rnd rounds to 4 decimals so that tiny components print as 0
// in both.)
#version 3.7;
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro T(O, P, D) #local N = <0,0,0>; #local H = trace(O, P, D, N); #debug concat(vstr(3, H, ",", 0, 4), " n ", vstr(3, Rnd(N), ",", 0, 4), "\n") #end
#declare U = union { sphere { 0, 1 } box { <2,0,0>, <3,1,1> } }
T(U, <-5, 0.5, 0>, x)
T(U, <2.5, 5, 0.5>, -y)
#declare D = difference { box { -1, 1 } sphere { <0, 1, 0>, 0.5 } }
T(D, <0.1, 5, 0>, -y)
T(D, <5, 0.2, 0.3>, -x)
#declare I = intersection { sphere { 0, 1 } cylinder { -2*y, 2*y, 0.5 } }
T(I, <-5, 0.1, 0>, x)
T(I, <0.2, 5, 0.1>, -y)
