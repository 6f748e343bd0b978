// stdlib-makegrass.pov: makegrass.inc's MakeBlade, MakeGrassPatch and
// MakePrairie through the extents of what they build, points (and, for
// smooth blades, normals turned to face the ray) found with trace(), and
// the meshes they #write, read back with #include. The expected output is
// POV-Ray's with its own makegrass.inc; the files written match POV-Ray's
// byte for byte (doc/stdlib.md).
#version 3.7;
#include "colors.inc" // POV-Ray's makegrass.inc needs Red for doTest
#include "makegrass.inc"
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ",", 0, 4) #end
#macro E(Name, O) #debug concat(Name, ": ", Str3(min_extent(O)), " / ", Str3(max_extent(O)), "\n") #end
#macro TN(O, P, D) #local N = <0,0,0>; #local H = trace(O, P, D, N);
	#if (vdot(N, D) > 0) #local N = -N; #end
	#debug concat("  ", Str3(H), " n ", Str3(N), "\n") #end
// A grid of rays straight down: the hits, in order.
#macro Down(O, X0, X1, Z0, Z1, Step)
	#local N = <0,0,0>;
	#local Count = 0;
	#for (X, X0, X1, Step)
		#for (Z, Z0, Z1, Step)
			#local H = trace(O, <X, 100, Z>, -y, N);
			#if (vlength(N) > 0)
				#debug concat("  ", Str3(H), "\n")
				#local Count = Count + 1;
			#end
		#end
	#end
	#debug concat("  hits ", str(Count, 0, 0), "\n")
#end

// One blade: bent back by startBend, down by vBend, turned and moved.
#declare B1 = mesh { MakeBlade(0, <1, 2, 3>, 30, 4, 10, 1, 0.3, 0.5, <0, 1, 0.3>, <0, -0.5, 0>, 3, 0, 0) }
E("blade", B1)
TN(B1, <1, 5, -10>, z)
TN(B1, <2, 8, -10>, z)
TN(B1, <2, 12.5, 3>, -y)
// Folded, smooth, bending sideways; other powers.
#declare B2 = mesh { MakeBlade(1, <0, 0, 0>, -20, 5, 8, 1, 0.2, 0.6, <0.2, 1, 0.3>, <0.3, -0.5, 1>, 2, 1, 0) }
E("folded smooth blade", B2)
TN(B2, <0, 2, -10>, z)
TN(B2, <0.3, 4, -10>, z)
TN(B2, <-0.2, 1, 10>, -z)
TN(B2, <0.2, 5, -10>, z)
#declare B3 = mesh { MakeBlade(0, <0, 0, 0>, 0, 8, 8, 1, 1, 0, <0, 1, 0>, <0, 0, 1>, 1, 1, 0) }
E("pw 1", B3)
#declare B3 = mesh { MakeBlade(0, <0, 0, 0>, 0, 8, 8, 1, 1, 0, <0, 1, 0>, <0, 0, 1>, 3, 0, 0) }
E("pw 3", B3)
// Written to a file and read back.
#fopen filehandle "makegrass-blade.txt" write
MakeBlade(1, <1, 0, -1>, 45, 3, 6, 0.5, 0.1, 0.3, <0, 1, 0.2>, <0, 0.5, 1>, 2, 1, 1)
#fclose filehandle
#declare B4 = mesh { #include "makegrass-blade.txt" }
E("blade from file", B4)
TN(B4, <1.8, 4, -10>, z)
// (The grid is shifted off x - z = 2, the fold line, on which POV-Ray's
// trace() falls through the edge between two triangles and lucent's does not.)
Down(B4, 0.6123, 3.4, -1.4, 1.4, 0.2)

// Patches: 3 x 3 blades, every random deviation used.
#declare P1 = MakeGrassPatch(10, 3, 15, 3, 2, 1, 0.5, 0, <0, 1, 0.2>, <0, 0.3, 1>, 2, 17, 0.7, 100, 1.5, 2, 0, 0, "")
E("patch", P1)
Down(P1, -6, 6, -6, 6, 0.5)
#declare P2 = MakeGrassPatch(50, 4, 0, 6, 25, 1, 0.3, 1, <0, 1, 0.3>, <0, -0.5, 0>, 3, 459, 1, 360, 1.2, 2, 1, 0, "")
E("folded smooth patch", P2)
Down(P2, -40, 40, -32, 33, 5)
MakeGrassPatch(20, 2, 0, 4, 10, 1, 0.1, 0, <0, 1, 0.3>, <0, 1, 2>, 4, 5153, 1, 360, 1.2, 10, 0, 1, "makegrass-patch.txt")
#declare P3 = #include "makegrass-patch.txt"
E("patch from file", P3)
Down(P3, -15, 15, -15, 15, 1)

// Prairies of a small box, rows widening by whole and half patches.
#declare R = seed(459);
#declare O = box { <0, 0, 0>, <0.3, 0.05, 0.1> }
#declare Q1 = MakePrairie(1, 3, 0.5, 3, O, 7, 0.3, 1, 0)
E("prairie", Q1)
Down(Q1, -3, 3, -1, 4, 0.23)
#declare Q2 = MakePrairie(1.5, 2, 1.5, 2, O, R, 0.5, 0.2, 0)
E("prairie 2", Q2)
Down(Q2, -3, 3, -1, 4, 0.23)
// doTest: ellipsoids, turned by numbers from the stream R itself.
#declare Q3 = MakePrairie(1, 3, 1, 2, O, R, 0.5, 0.2, 1)
E("test prairie", Q3)
Down(Q3, -3, 3, -1, 4, 0.31)
#debug concat("next of R: ", str(rand(R), 0, 6), "\n")
