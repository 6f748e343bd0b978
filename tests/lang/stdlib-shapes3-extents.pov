// stdlib-shapes3-extents.pov: min_extent and max_extent of shapes3.inc's
// macros over a range of their parameters. POV-Ray's bounding boxes show
// how its macros build the shapes (which pieces are turned, what cuts
// them), so lucent's shapes3.inc builds them the same way: the expected
// text is POV-Ray's with its own shapes3.inc. Angles are chosen so that no
// figure lies on a rounding edge of the 4th decimal (POV-Ray keeps boxes
// in single precision).
#version 3.7;
#include "shapes3.inc"
// Rnd(V): V rounded to 4 decimals.
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro E(Name, Obj)
	#debug concat(Name, ": ", vstr(3, Rnd(min_extent(Obj)), ",", 0, 4), " / ", vstr(3, Rnd(max_extent(Obj)), ",", 0, 4), "\n")
#end
#declare Angles = array[22] { -1000, -550, -400, -360, -290, -220, -180, -135, -100, -45, 0,
	20, 45, 100, 135, 180, 210, 300, 360, 400, 550, 720 }
#for (I, 0, 21)
	#declare A = Angles[I];
	E(concat("Segment_of_Torus ", str(A, 0, 0)), Segment_of_Torus(2, 0.5, A))
	E(concat("Segment_of_CylinderRing ", str(A, 0, 0)), Segment_of_CylinderRing(2, 1.5, 1, A))
	E(concat("Segment_of_Object ", str(A, 0, 0)), Segment_of_Object(box { <-1, -1, -2>, <1.5, 1, 0.8> }, A))
#end
E("Segment_of_Torus thick", Segment_of_Torus(1, 2, 45))
E("Segment_of_CylinderRing R_in > R_out", Segment_of_CylinderRing(1, 1.5, 1, 45))
E("Segment_of_CylinderRing Height < 0", Segment_of_CylinderRing(2, 1.5, -1, 45))
E("Segment_of_Object sphere", Segment_of_Object(sphere { <0.5, 0, 0>, 1 }, 200))
E("Segment_of_Object tall", Segment_of_Object(box { <-1, -5, -1>, <1, 7, 4> }, 200))
#for (N, 3, 9)
	E(concat("Column_N ", str(N, 0, 0)), Column_N(N, 1, 2))
#end
E("Column_N wide", Column_N(6, 2, 0.5))
E("Column_N_AB", Column_N_AB(5, <0,0,0>, <1,2,0.5>, 0.5))
E("Pyramid_N", Pyramid_N(5, 1, 0.4, 2))
E("Pyramid_N wider top", Pyramid_N(5, 0.4, 1, 2))
E("Pyramid_N to a point", Pyramid_N(5, 1, 0, 2))
E("Pyramid_N 3", Pyramid_N(3, 2, 1, 3))
E("Pyramid_N 6 down", Pyramid_N(6, 1, 2, -1))
E("Pyramid_N_AB", Pyramid_N_AB(7, <0,0,0>, 1, <0.5,2,1>, 0.3))
E("Facetted_Sphere 3 8", Facetted_Sphere(3, 8))
E("Facetted_Sphere 2 5", Facetted_Sphere(2, 5))
E("Facetted_Sphere 1 3", Facetted_Sphere(1, 3))
E("Facetted_Egg_Shape", Facetted_Egg_Shape(2, 5, 1.6, 1.2))
E("Facetted_Egg 4 10", Facetted_Egg(4, 10))
E("Facetted_Egg 2 6", Facetted_Egg(2, 6))
E("Egg_Shape 1.2 1.6", Egg_Shape(1.2, 1.6))
E("Egg_Shape 2 0.5", Egg_Shape(2, 0.5))
E("Egg", Egg)
E("Round_Conic_Torus", Round_Conic_Torus(1, 0.5, 1, 0.2, 0))
E("Round_Conic_Torus equal", Round_Conic_Torus(1, 1, 1, 0.2, 0))
E("Round_Conic_Torus upper larger", Round_Conic_Torus(2, 1, 0.5, 0.2, 1))
E("Round_Conic_Torus far", Round_Conic_Torus(5, 0.3, 1, 0.1, 0))
E("Round_Conic_Prism", Round_Conic_Prism(1, 0.5, 1, 2, 0.2, 1))
E("Round_Conic_Prism upper larger", Round_Conic_Prism(2, 1, 0.5, 3, 0.2, 0))
E("Round_Conic_Prism far", Round_Conic_Prism(5, 0.3, 1, 1, 0.1, 0))
E("Half_Hollowed_Rounded_Cylinder1", Half_Hollowed_Rounded_Cylinder1(3, 1, 0.1, 1.5, 0))
E("Half_Hollowed_Rounded_Cylinder1 flat rim", Half_Hollowed_Rounded_Cylinder1(4, 0.5, 0.2, 0.5, 1))
E("Half_Hollowed_Rounded_Cylinder2", Half_Hollowed_Rounded_Cylinder2(3, 1, 0.2, 0.1, 1.5, 1))
E("Half_Hollowed_Rounded_Cylinder2 tall rim", Half_Hollowed_Rounded_Cylinder2(2, 0.6, 0.1, 0.05, 3, 0))
E("Rounded_Tube_AB slanting", Rounded_Tube_AB(<0,0,0>, <1,2,0.5>, 1, 0.5, 0.1, 0))
E("Rounded_Tube_AB slanting down", Rounded_Tube_AB(<1,0,2>, <-1,-2,3>, 1, 0.5, 0.1, 0))
E("Rounded_Tube_AB along x", Rounded_Tube_AB(<0,0,0>, <2,0,0>, 1, 0.5, 0.1, 0))
E("Rounded_Tube_AB down y", Rounded_Tube_AB(<0,0,0>, <0,-2,0>, 1, 0.5, 0.1, 0))
E("Rounded_Tube_AB down z", Rounded_Tube_AB(<0,0,0>, <0,0,-2>, 1, 0.5, 0.1, 1))
