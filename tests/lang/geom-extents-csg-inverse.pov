// checks min_extent/max_extent of intersections and differences whose parts hold inverse
// objects, and trace()/inside() on them: POV-Ray's union box includes its inverse parts'
// boxes, an intersection's box is the intersection of its parts' boxes leaving inverse parts
// out, and trace() skips an object (or a part of a union, merge or intersection) whose box the
// ray misses -- which cuts off the surface of such an intersection outside its box.
#version 3.7;
#macro P(N, O) #debug concat(N, " ", vstr(3, min_extent(O), ",", 0, 6), "  ", vstr(3, max_extent(O), ",", 0, 6), "\n") #end
P("u-inv", union { sphere { 0, 1 inverse } sphere { 3*x, 1 } })
P("i-u-inv", intersection { box { -2, 2 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } })
P("i-u-inv2", intersection { union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } box { -2, 2 } })
P("i-u-inv3", intersection { box { -5, 5 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } })
P("i-u-invplane", intersection { box { -2, 2 } union { plane { y, 0 inverse } sphere { 3*x, 1 } } })
P("i-u-plane", intersection { box { -2, 2 } union { plane { y, 0 } sphere { 3*x, 1 } } })
P("i-u-plane2", intersection { box { -2, 2 } union { plane { y, 0 } sphere { 3*y, 1 } } })
P("i-m-inv", intersection { box { -2, 2 } merge { sphere { 0, 1 inverse } sphere { 3*x, 1 } } })
P("i-i-inv", intersection { box { -2, 2 } intersection { sphere { 0, 1 inverse } sphere { x, 1 } } })
P("i-d", intersection { box { -2, 2 } difference { sphere { 0, 3 } sphere { x, 1 } } })
P("i-d-inv", intersection { box { -2, 2 } difference { sphere { 0, 1 inverse } sphere { x, 1 } } })
P("i-uinv", intersection { box { -2, 2 } union { sphere { 0, 1 } sphere { 3*x, 1 } inverse } })
P("i-uinv-2", intersection { box { -2, 2 } union { sphere { 0, 1 } sphere { 3*x, 1 } } inverse })
P("d-u-inv", difference { box { -2, 2 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } })
P("d-u", difference { box { -2, 2 } union { sphere { 0, 1 } sphere { 3*x, 1 } } })
P("d-uinv", difference { box { -2, 2 } union { sphere { 0, 1 } sphere { 3*x, 1 } inverse } })
P("d-plane-inv", difference { box { -2, 2 } plane { y, 0 inverse } })
P("d-sph-inv", difference { box { -2, 2 } sphere { 0, 1 inverse } })
P("d-sph-inv2", difference { box { -2, 2 } sphere { 0, 5 inverse } })
P("i-sph-inv", intersection { box { -2, 2 } sphere { 0, 1 inverse } })
P("u-in-i", union { intersection { box { -2, 2 } sphere { 0, 1 inverse } } sphere { 5*x, 1 } })
P("u-all-inv", union { sphere { 0, 1 inverse } sphere { 3*x, 1 inverse } })
P("i-nested-u", intersection { box { -2, 2 } union { union { sphere { 0, 1 inverse } } sphere { 3*x, 1 } } })
P("i-u-invplane-tr", intersection { box { -2, 2 } union { plane { y, 0 inverse } sphere { 3*x, 1 } } translate x })
P("i-u-inv-sc", intersection { box { -2, 2 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } scale 0.5 } })
P("i-u-inv-b", intersection { box { -2, 2 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } bounded_by { box { -1, 1 } } } })
P("i-obj-u-inv", intersection { box { -2, 2 } object { union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } } })
P("i-cyl-u-inv", intersection { cylinder { -5*x, 5*x, 1 } union { box { -1, 1 inverse } sphere { 3*x, 1 } } })
P("m-inv", merge { sphere { 0, 1 inverse } sphere { 3*x, 1 } })
P("i-u-plane-inv2", intersection { sphere { 0, 3 } union { plane { y, 1 inverse } plane { -y, 1 inverse } } })
#declare O = intersection { box { -2, 2 } union { sphere { 0, 1 inverse } sphere { 3*x, 1 } } }
#declare U2 = union { object { O } sphere { 10*x, 1 } }
#declare M2 = merge { object { O } sphere { 10*x, 1 } }
#declare D2 = difference { box { -3, 3 } object { O } }
#declare I2 = intersection { box { -3, 3 } object { O } }
#declare N = <0,0,0>;
#declare H = trace(U2, <1.5,1.5,-10>, z, N);
#debug concat("U2 ", vstr(3,H,",",0,6), "\n")
#declare H = trace(M2, <1.5,1.5,-10>, z, N);
#debug concat("M2 ", vstr(3,H,",",0,6), "\n")
#declare H = trace(D2, <1.5,1.5,-10>, z, N);
#debug concat("D2 ", vstr(3,H,",",0,6), "\n")
#declare H = trace(I2, <1.5,1.5,-10>, z, N);
#debug concat("I2 ", vstr(3,H,",",0,6), "\n")
#declare H = trace(D2, <1.5,1.5,-2.5>, z, N);
#debug concat("D2in ", vstr(3,H,",",0,6), "\n")
#debug concat("D2 inside ", str(inside(D2, <1.5,1.5,1.5>),0,0), "\n")
#declare U = union { sphere { 0, 1 inverse } sphere { 3*x, 1 } }
#debug concat("in ", str(inside(O, <1.5,1.5,1.5>),0,0), " ", str(inside(U, <-5,5,5>),0,0), "\n")
#declare H = trace(O, <1.5,1.5,-10>, z, N);
#debug concat("tr ", vstr(3,H,",",0,6), " n ", vstr(3,N,",",0,6), "\n")
#declare H = trace(O, <0.5,0.5,-10>, z, N);
#debug concat("tr ", vstr(3,H,",",0,6), " n ", vstr(3,N,",",0,6), "\n")
#declare H = trace(U, <-5,0.2,0>, x, N);
#debug concat("tr ", vstr(3,H,",",0,6), " n ", vstr(3,N,",",0,6), "\n")
#declare S = sphere { 0, 1 bounded_by { box { -0.5, 0.5 } } }
#declare H = trace(S, <0,0,-10>, z, N);
#debug concat("trb ", vstr(3,H,",",0,6), " n ", vstr(3,N,",",0,6), "\n")
#debug concat("inb ", str(inside(S, <0.8,0,0>),0,0), "\n")
