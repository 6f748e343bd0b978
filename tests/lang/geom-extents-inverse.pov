// checks min_extent/max_extent of inverted objects and of CSG objects holding them:
// POV-Ray reports an inverse object's box as it was, and a union's box includes its
// inverse parts' boxes; an intersection leaves its inverse parts out
#version 3.7;
#macro P(N, O) #debug concat(N, " ", vstr(3, min_extent(O), ",", 0, 6), "  ", vstr(3, max_extent(O), ",", 0, 6), "\n") #end
P("sph-inv", sphere { 0, 1 inverse })
P("sph-inv-tr", sphere { 0, 1 inverse translate x scale 2 })
P("sph-tr-inv", sphere { 0, 1 translate x inverse })
P("box-inv", box { -1, <2,3,4> inverse })
P("plane-inv", plane { y, 1 inverse })
P("union-inv-kid", union { sphere { 0, 1 inverse } sphere { 3*x, 1 } })
P("union-inv", union { sphere { 0, 1 } sphere { 3*x, 1 } inverse })
P("merge-inv", merge { sphere { 0, 1 } sphere { 3*x, 1 } inverse })
P("isect-inv-kid", intersection { box { -2, 2 } sphere { 0, 1 inverse } })
P("isect-inv", intersection { box { -2, 2 } sphere { 0, 1.5 } inverse })
P("diff-inv", difference { box { -2, 2 } sphere { 0, 1 } inverse })
P("diff-inv-kid", difference { box { -2, 2 } sphere { 0, 1 inverse } })
P("isect-inv-kids", intersection { sphere { 0, 1 inverse } sphere { x, 1 inverse } })
P("isect-box-invbox", intersection { box { -1, 1 } box { -0.5, 0.5 inverse } })
P("torus-inv", torus { 2, 0.5 inverse })
P("sph-inv-clip", sphere { 0, 1 inverse clipped_by { box { -0.5, 0.5 } } })
P("sph-inv-bound", sphere { 0, 1 inverse bounded_by { box { -3, 3 } } })
P("union-inv-plane", union { sphere { 0, 1 } plane { y, 0 } inverse })
P("obj-inv", object { sphere { 0, 1 } inverse })
#declare S = sphere { 0, 1 inverse }
P("obj-of-inv", object { S translate y })
P("obj-of-inv-inv", object { S inverse })
P("cone-inv", cone { 0, 2, y, 1 inverse })
P("union-inv-kid-scaled", union { sphere { 0, 1 inverse } sphere { 3*x, 1 } scale 2 translate y })
P("union-nested-inv", union { union { sphere { 0, 1 inverse } box { 1, 2 } } sphere { -3*x, 1 } })
P("union-isect-inv", union { intersection { sphere { 0, 1 inverse } sphere { x, 1 inverse } } sphere { 3*x, 1 } })
P("plane-inv-bound", plane { y, 1 inverse bounded_by { box { -2, 2 } } })
