// stdlib-shapesq.pov: the polynomial surfaces of shapesq.inc through
// inside() on a grid of points, the points where rays meet them, and
// extents (all are infinite but the clipped helices).
#version 3.7;
#include "shapes.inc"
#include "shapesq.inc"
// Rnd(V): V rounded to 4 decimals (no -0).
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ",", 0, 4) #end
// Show(Name, O, Sc): inside() at the 27 points of the grid {-1, 0.3, 0.8}^3
// scaled by Sc (as 0 and 1), then the first hits of rays from 12
// directions at distance 10 Sc aimed at points near the origin (or
// "miss").
#declare Grid = array[3] { -1, 0.3, 0.8 }
#declare Rays = array[12][2] {
	{ <1.3, 9.7, 0.6>, <0.05, 0.01, 0.02> }, { <0.7, -9.6, 1.1>, <0.1, 0.2, 0.03> },
	{ <9.5, 1.3, 0.9>, <0.02, 0.1, 0.04> }, { <-9.4, 1.2, 1.6>, <0.3, 0.03, 0.1> },
	{ <1.2, 0.8, 9.3>, <0.01, 0.2, 0.3> }, { <0.9, 1.4, -9.5>, <0.2, 0.04, 0.1> },
	{ <6, 7, -5>, <0.4, 0.2, 0.1> }, { <-7, 5, 6>, <0.1, 0.3, 0.2> },
	{ <5, -6, 7>, <0.2, 0.1, 0.4> }, { <-6, -5, -7>, <0.3, 0.3, 0.3> },
	{ <9, 1, 2>, <0.5, 0.6, 0.7> }, { <2, 9, -1>, <0.7, 0.5, 0.3> }
}
#macro Show(Name, O, Sc)
	#debug concat(Name, ": ", Str3(min_extent(O)), " / ", Str3(max_extent(O)), "\n  inside ")
	#for (I, 0, 2) #for (J, 0, 2) #for (K, 0, 2)
		#debug str(inside(O, <Grid[I], Grid[J], Grid[K]> * Sc), 0, 0)
	#end #end #end
	#debug "\n "
	#local N = <0, 0, 0>;
	#for (I, 0, 11)
		#local From = Rays[I][0] * Sc;
		#local P = trace(O, From, Rays[I][1] * Sc - From, N);
		#if (vlength(N) > 0)
			#debug concat(" ", Str3(P))
		#else
			#debug " miss"
		#end
		#if (mod(I, 4) = 3) #debug "\n " #end
	#end
	#debug "\n"
#end
Show("Bicorn", Bicorn, 1)
Show("Crossed_Trough", Crossed_Trough, 1)
Show("Cubic_Cylinder", Cubic_Cylinder, 1)
Show("Cubic_Saddle_1", Cubic_Saddle_1, 1)
Show("Devils_Curve", Devils_Curve, 1)
Show("Folium", Folium, 1)
Show("Glob_5", Glob_5, 1)
Show("Twin_Glob", Twin_Glob, 1)
Show("Helix", Helix, 1)
Show("Helix_1", Helix_1, 1)
Show("Hyperbolic_Torus_40_12", Hyperbolic_Torus_40_12, 8)
Show("Lemniscate", Lemniscate, 1)
Show("Quartic_Loop_1", Quartic_Loop_1, 1)
Show("Monkey_Saddle", Monkey_Saddle, 1)
Show("Parabolic_Torus_40_12", Parabolic_Torus_40_12, 8)
Show("Piriform", Piriform, 1)
Show("Quartic_Paraboloid", Quartic_Paraboloid, 1)
Show("Quartic_Cylinder", Quartic_Cylinder, 1)
Show("Steiner_Surface", Steiner_Surface, 1)
Show("Torus_40_12", Torus_40_12, 8)
Show("Witch_Hat", Witch_Hat, 1)
Show("Sinsurf", Sinsurf, 1)
