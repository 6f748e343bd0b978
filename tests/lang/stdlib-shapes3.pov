// stdlib-shapes3.pov: the macros of shapes3.inc through the points where
// rays from 29 directions aimed at a chosen point meet them, inside() at
// that point, and (for the calls whose last argument is 1) their extents.
// The extents of more calls are in stdlib-shapes3-extents.pov. Left out:
// the extents of Round_Pyramid_N_out/_in, Round_Cylinder_Tube and
// Rounded_Tube from A to B off the y axis, and Round_N_Tube_Polygon, whose
// bounding boxes in POV-Ray come from ways of building them not yet
// worked out (doc/stdlib.md).
#version 3.7;
#include "shapes3.inc"
// Rnd(V): V rounded to 4 decimals (no -0).
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ",", 0, 4) #end
#declare Dirs = array[29]
#declare K = 0;
#for (I, -1, 1) #for (J, -1, 1) #for (L, -1, 1)
	#if (I != 0 | J != 0 | L != 0)
		#declare Dirs[K] = vnormalize(<I, J, L>);
		#declare K = K + 1;
	#end
#end #end #end
#declare Dirs[26] = vnormalize(<0.3, 0.8, -0.5>);
#declare Dirs[27] = vnormalize(<-0.7, 0.2, 0.4>);
#declare Dirs[28] = vnormalize(<0.1, -0.6, 0.9>);
// Probe(Name, Obj, C0, R, Ext): the hits of rays from distance R aimed at
// C0 (a little off it), inside() there, and the extents when Ext.
#macro Probe(Name, Obj, C0, R, Ext)
	#if (Ext)
		#debug concat(Name, ": ", Str3(min_extent(Obj)), " / ", Str3(max_extent(Obj)), "\n")
	#else
		#debug concat(Name, ":\n")
	#end
	#local C = C0 + <0.01, 0.02, 0.03>;
	#local S = "";
	#for (I, 0, 28)
		#local N = <0, 0, 0>;
		#local H = trace(Obj, C + R * Dirs[I], -Dirs[I], N);
		#if (vlength(N) = 0)
			#local S = concat(S, " -");
		#else
			#local S = concat(S, " ", Str3(H));
		#end
		#if (mod(I, 3) = 2)
			#debug concat(S, "\n")
			#local S = "";
		#end
	#end
	#debug concat(S, " in ", str(inside(Obj, C), 0, 0), "\n")
#end
Probe("Segment_of_Torus", object { Segment_of_Torus(2, 0.5, 120) }, 0, 5, 1)
Probe("Segment_of_Torus negative", object { Segment_of_Torus(2, 0.5, -60) }, 0, 5, 0)
Probe("Segment_of_Torus 300", object { Segment_of_Torus(2, 0.5, 300) }, 0, 5, 0)
Probe("Segment_of_CylinderRing", object { Segment_of_CylinderRing(2, 1.5, 1, 100) }, 0, 5, 1)
Probe("Segment_of_CylinderRing 250", object { Segment_of_CylinderRing(2, 1.5, 1, 250) }, 0, 5, 0)
Probe("Segment_of_Torus 400", object { Segment_of_Torus(2, 0.5, 400) }, 0, 5, 0)
Probe("Segment_of_CylinderRing 0", object { Segment_of_CylinderRing(2, 1.5, 1, 0) }, <0,0.5,0>, 5, 0)
Probe("Segment_of_CylinderRing -400", object { Segment_of_CylinderRing(2, 1.5, 1, -400) }, <0,0.5,0>, 5, 0)
Probe("Segment_of_CylinderRing R_in > R_out", object { Segment_of_CylinderRing(1, 1.5, 1, 45) }, <0,0.5,0>, 5, 0)
Probe("Segment_of_Object", object { Segment_of_Object(sphere { <0.5,0,0>, 1 }, 135) }, 0, 5, 1)
Probe("Column_N", object { Column_N(6, 1, 2) }, 0, 5, 1)
Probe("Column_N_AB", object { Column_N_AB(5, <0,0,0>, <1,2,0.5>, 0.5) }, 0, 5, 1)
Probe("Pyramid_N", object { Pyramid_N(5, 1, 0.4, 2) }, 0, 5, 1)
Probe("Pyramid_N wider top", object { Pyramid_N(6, 1, 2, 1) }, <0,0.5,0>, 5, 1)
Probe("Pyramid_N_AB", object { Pyramid_N_AB(7, <0,0,0>, 1, <0.5,2,1>, 0.3) }, 0, 5, 1)
Probe("Facetted_Sphere", object { Facetted_Sphere(3, 8) }, 0, 5, 1)
Probe("Facetted_Egg_Shape", object { Facetted_Egg_Shape(3, 8, 1.2, 1.6) }, 0, 5, 1)
Probe("Facetted_Egg", object { Facetted_Egg(4, 10) }, <0, 1, 0>, 5, 1)
Probe("Egg_Shape", object { Egg_Shape(1.2, 1.6) }, <0, 1, 0>, 5, 1)
Probe("Egg", object { Egg }, <0, 1, 0>, 5, 1)
Probe("Ring_Sphere", object { Ring_Sphere(2, 2, 0.2, 0.15, 5, 6) }, 0, 5, 1)
Probe("Ring_Sphere thin", object { Ring_Sphere(1.5, 2, 0.1, 0.25, 3, 4) }, 0, 5, 1)
Probe("Ring_Sphere odd", object { Ring_Sphere(2, 1.8, 0.3, 0.1, 4, 5) }, <0,1.2,0>, 5, 1)
Probe("Ring_Sphere bare", object { Ring_Sphere(1, 3, 0.05, 0.4, 0, 1) }, 0, 5, 1)
Probe("Round_Pyramid_N_out", object { Round_Pyramid_N_out(6, <0,0,0>, 1, <0,2,0>, 0.5, 0.1, 1, 0) }, <0,1,0>, 5, 0)
Probe("Round_Pyramid_N_out hollow", object { Round_Pyramid_N_out(5, <0,0,0>, 1, <0.5,2,0>, 0.5, 0.1, 0, 0) }, <0,1,0>, 5, 0)
Probe("Round_Pyramid_N_in", object { Round_Pyramid_N_in(6, <0,0,0>, 1, <0,2,0>, 0.5, 0.1, 1, 0) }, <0,1,0>, 5, 0)
Probe("Round_Cylinder_Tube", object { Round_Cylinder_Tube(<0,0,0>, <0,2,0>, 1, 0.2, 0, 0) }, <0,1,0>, 5, 1)
Probe("Round_Cylinder_Tube filled", object { Round_Cylinder_Tube(<0,0,0>, <1,2,0>, 1, 0.2, 1, 1) }, <0.5,1,0>, 5, 0)
Probe("Rounded_Tube", object { Rounded_Tube(1, 0.6, 0.1, 2, 0) }, <0,1,0>, 5, 1)
Probe("Rounded_Tube_AB", object { Rounded_Tube_AB(<0,0,0>, <1,2,0.5>, 1, 0.6, 0.1, 1) }, <0.5,1,0.25>, 5, 0)
Probe("Round_Conic_Torus", object { Round_Conic_Torus(1, 0.5, 1, 0.2, 0) }, <0,0.5,0>, 5, 1)
Probe("Round_Conic_Prism", object { Round_Conic_Prism(1, 0.5, 1, 2, 0.2, 1) }, <0,0.5,-1>, 5, 1)
Probe("Half_Hollowed_Rounded_Cylinder1", object { Half_Hollowed_Rounded_Cylinder1(3, 1, 0.1, 1.5, 0) }, 0, 5, 1)
Probe("Half_Hollowed_Rounded_Cylinder2", object { Half_Hollowed_Rounded_Cylinder2(3, 1, 0.2, 0.1, 1.5, 1) }, 0, 5, 1)
Probe("Round_N_Tube_Polygon", object { Round_N_Tube_Polygon(6, 0.1, 1, 0.3, 0, 0) }, 0, 5, 0)
Probe("Round_N_Tube_Polygon filled", object { Round_N_Tube_Polygon(5, 0.1, 1, 0.3, 1, 1) }, 0, 5, 0)
