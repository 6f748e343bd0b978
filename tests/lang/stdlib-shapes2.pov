// stdlib-shapes2.pov: the shapes of shapes2.inc through their extents,
// the points where rays from 26 directions around them (and a few more)
// meet them, and inside() at chosen points.
#version 3.7;
#include "shapes.inc"
#include "shapes2.inc"
// Rnd(V): V rounded to 4 decimals (no -0).
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ",", 0, 4) #end
#declare Dirs = array[30]
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
#declare Dirs[29] = vnormalize(<0.5, 0.1, 0.2>);
#macro Show(Name, O)
	#debug concat(Name, ": ", Str3(min_extent(O)), " / ", Str3(max_extent(O)), "\n")
	#local N = <0, 0, 0>;
	#for (I, 0, 29)
		#local P = trace(O, Dirs[I] * 20 + <0.01, 0.02, 0.03>, -Dirs[I], N);
		#if (vlength(N) > 0)
			#debug concat(" ", Str3(P))
		#else
			#debug " miss"
		#end
		#if (mod(I, 6) = 5) #debug "\n" #end
	#end
#end
#macro In(Name, O, Pts)
	#debug concat(Name, " inside:")
	#for (I, 0, dimension_size(Pts, 1) - 1)
		#debug concat(" ", str(inside(O, Pts[I]), 0, 0))
	#end
	#debug "\n"
#end
Show("Tetrahedron", Tetrahedron)
In("Tetrahedron", Tetrahedron, array[6] { <0, 0, 0>, <0, 2.9, 0>, <0, 3.1, 0>, <0, -1.1, 0>, <1.5, -0.9, 0.5>, <0, -0.9, -1.5> })
Show("Octahedron", Octahedron)
In("Octahedron", Octahedron, array[6] { <0, 1.7, 0>, <0, 1.75, 0>, <1.2, 0, 1.2>, <1.25, 0, 1.25>, <1.2, 0, 0>, <1.3, 0, 0> })
Show("Dodecahedron", Dodecahedron)
In("Dodecahedron", Dodecahedron, array[4] { <0, 0.99, 0>, <0, 1.01, 0>, <0.7, 0.7, 0.7>, <0.75, 0.75, 0.75> })
Show("Icosahedron", Icosahedron)
In("Icosahedron", Icosahedron, array[4] { <0, 1.25, 0>, <0, 1.26, 0>, <0.7, 0.7, 0.7>, <0.75, 0.75, 0.75> })
Show("Rhomboid", Rhomboid)
In("Rhomboid", Rhomboid, array[4] { <1.7, 0.99, 0>, <1.7, 0.8, 0>, <-1.1, 0, 0.5>, <-1.2, 0, 0.5> })
Show("Hexagon", Hexagon)
In("Hexagon", Hexagon, array[4] { <0, 1.1, 0>, <0, 1.16, 0>, <0.99, 0, 0>, <0, 0.6, 0.98> })
Show("HalfCone_Y", HalfCone_Y)
In("HalfCone_Y", HalfCone_Y, array[4] { <0, 0.5, 0>, <0.37, 0.5, 0>, <0.38, 0.5, 0>, <0, 1.01, 0> })
Show("Pyramid", Pyramid)
Show("Pyramid2", Pyramid2)
In("Pyramid2", Pyramid2, array[6] { <0, -0.5, 0>, <1.2, -0.95, 0>, <0, 0.5, 0>, <0, 0.6, 0>, <0, -1.1, 0>, <0.9, -0.95, 0.9> })
Show("Square_X", Square_X)
Show("Square_Y", Square_Y)
Show("Square_Z", Square_Z)
