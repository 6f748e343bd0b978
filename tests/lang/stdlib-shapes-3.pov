// stdlib-shapes-3.pov: shapes.inc's Supercone and HF macros (HF_Square,
// HF_Sphere, HF_Cylinder, HF_Torus), through the extents of the objects
// (the vertices of the meshes), heights and radii found with trace, and
// inside(); and the files shapes.inc brings in (consts, math, transforms,
// strings).
#version 3.7;
#include "shapes.inc"
// Rnd(V): V rounded to 4 decimals, so that the tiny padding POV-Ray adds to
// some bounding boxes does not show.
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Str3(V) vstr(3, Rnd(V), ", ", 0, 4) #end
#macro Show(Name, O)
	#debug concat(Name, ": ", Str3(min_extent(O)), " / ", Str3(max_extent(O)), "\n")
#end
#declare N = <0, 0, 0>;
// Hit(O, From, Dir): the first intersection of the ray, rounded.
#macro Hit(O, From, Dir) Str3(trace(O, From, Dir, N)) #end
// Dist(Name, O, C, Dirs, R0): for each direction D, the distance from C of
// the surface met coming from far along D, less R0. (No direction lies on
// the seam where u = 0 meets u = 1: what a ray meets there depends on how
// the two edges' triangles are hit.)
#macro Dist(Name, O, C, Dirs, R0)
	#debug concat(Name, ":")
	#for (I, 0, dimension_size(Dirs, 1) - 1)
		#local P = trace(O, C + Dirs[I] * 100, -Dirs[I], N);
		#debug concat(" ", str(vlength(P - C) - R0, 0, 4))
	#end
	#debug "\n"
#end

// The included files.
#debug concat("consts ", vstr(3, xz, ",", 0, 0), " ", str(Water_Ior, 0, 3), "\n")
#debug concat("math ", str(sind(30), 0, 4), " ", vstr(3, VPerp_To_Vector(z), ",", 0, 0), "\n")
#debug concat("strings ", VStr(<1, 2, 3>), "\n")
Show("transforms", object { sphere { 0, 1 } Axis_Rotate_Trans(y, 90) translate x })

// Center_Object and Align_Object through Center_Trans and Align_Trans.
#declare B = box { <1, 2, 3>, <2, 4, 7> }
Show("Center_Object y", Center_Object(B, y))
Show("Align_Object +x-y+z", Align_Object(B, <1, -1, 1>, <0, 1, 2>))

// Supercone: ellipses A x B at EndA to C x D at EndB.
#declare S = Supercone(<0, 0, 0>, 1, 2, <0, 0, 3>, 3, 4);
Show("Supercone z", S)
#for (Z, 0.5, 2.5, 1)
	#debug concat("  z=", str(Z, 0, 1), " x ", Hit(S, <10, 0, Z>, -x), " y ", Hit(S, <0, 10, Z>, -y), " diagonal ", Hit(S, <10, 10, Z>, <-1, -1, 0>), "\n")
#end
#debug concat("  caps ", Hit(S, <0.3, 0.3, -10>, z), " ", Hit(S, <0.3, 0.3, 10>, -z), "\n")
#debug concat("  inside ", str(inside(S, <0, 0, 1.5>), 0, 0), str(inside(S, <0, 0, -0.1>), 0, 0), str(inside(S, <0, 0, 3.1>), 0, 0),
	str(inside(S, <1.9, 0, 1.5>), 0, 0), str(inside(S, <2.1, 0, 1.5>), 0, 0), str(inside(S, <0, 2.9, 1.5>), 0, 0), str(inside(S, <0, 3.1, 1.5>), 0, 0), "\n")
#declare S = Supercone(<0, 0, 0>, 1, 2, <0, 5, 0>, 3, 4);
Show("Supercone y", S)
#debug concat("  y=2.5 x ", Hit(S, <10, 2.5, 0>, -x), " z ", Hit(S, <0, 2.5, 10>, -z), "\n")
#declare S = Supercone(<0, 0, 0>, 1, 2, <3, 0, 0>, 3, 4);
Show("Supercone x", S)
#debug concat("  x=1.5 y ", Hit(S, <1.5, 10, 0>, -y), " z ", Hit(S, <1.5, 0, 10>, -z), "\n")
#declare S = Supercone(<1, 2, 3>, 1, 2, <1, 2, 7>, 0.5, 0.25);
Show("Supercone moved", S)
#declare S = Supercone(<0, 0, 0>, 1, 2, <0, 0, -3>, 3, 4);
Show("Supercone -z", S)
#debug concat("  z=-1.5 x ", Hit(S, <10, 0, -1.5>, -x), " y ", Hit(S, <0, 10, -1.5>, -y), "\n")
#declare S = Supercone(<0, 0, 0>, 3, 1, <0, 0, 3>, 1, 3);
Show("Supercone crossed", S)
#debug concat("  inside ", str(inside(S, <0, 0, 1.5>), 0, 0), str(inside(S, <1.9, 0, 1.5>), 0, 0), str(inside(S, <2.1, 0, 1.5>), 0, 0), "\n")

// HF_Square: UV heights (u along x, v along z), the resolution counting
// points, heights from the points of the base when not UV.
#declare F = function (x, y, z) { x * x }
#declare H = HF_Square(F, 1, 0, <3, 3>, 0, "", <0, 0, 0>, <1, 1, 1>)
Show("HF_Square x^2", H)
#debug "  heights"
#for (X, 0.05, 1, 0.1)
	#debug concat(" ", str(trace(H, <X, 5, 0.3>, -y, N).y, 0, 4))
#end
#debug "\n"
#declare FZ = function (x, y, z) { y }
#declare H = HF_Square(FZ, 1, 0, <3, 3>, 0, "", <0, 0, 0>, <1, 1, 1>)
#debug concat("HF_Square v along z: ", Hit(H, <0.3, 5, 0.05>, -y), " ", Hit(H, <0.3, 5, 0.65>, -y), "\n")
#declare H = HF_Square(function { x }, 1, 0, <4, 4>, 0, "", <-1, 2, -3>, <3, 5, 7>)
Show("HF_Square box", H)
#debug concat("  ", Hit(H, <-0.5, 50, 0.3>, -y), " ", Hit(H, <2.5, 50, 0.3>, -y), "\n")
#declare G = function (x, y, z) { 0.5 + 0.3 * x + 0.1 * z + 0.05 * y }
#declare H = HF_Square(G, 0, 0, <5, 3>, 0, "", <-1, 2, -3>, <3, 5, 7>)
Show("HF_Square not UV", H)
#debug concat("  ", Hit(H, <0, 50, 0.3>, -y), " ", Hit(H, <1, 50, 0.3>, -y), " ", Hit(H, <0.3, 50, -3>, -y), " ", Hit(H, <0.3, 50, 4.5>, -y), "\n")
#declare H = HF_Square(G, 0, 1, <6, 6>, 1, "", <0, 0, 0>, <1, 1, 1>)
Show("HF_Square smooth uv", H)

// HF_Sphere, HF_Cylinder, HF_Torus: extents, and the way u and v wrap.
Show("HF_Sphere 0.5", HF_Sphere(function { 0.5 }, 1, 0, <8, 8>, 0, "", <1, 2, 3>, 2, 1))
Show("HF_Sphere 0", HF_Sphere(function { 0 }, 1, 0, <8, 8>, 0, "", <0, 0, 0>, 2, 0.5))
Show("HF_Sphere 1", HF_Sphere(function { 1 }, 1, 0, <9, 9>, 0, "", <0, 0, 0>, 2, 0.5))
Show("HF_Sphere uv", HF_Sphere(function { 0.5 }, 1, 1, <8, 6>, 0, "", <0, 0, 0>, 2, 0.5))
#declare FU = function (x, y, z) { x }
#declare FV = function (x, y, z) { y }
Dist("HF_Sphere u at +z -x -z", HF_Sphere(FU, 1, 0, <13, 7>, 0, "", <0, 0, 0>, 2, 1), <0, 0, 0>, array[3] { z, -x, -z }, 2)
Dist("HF_Sphere v at +x +x+y +x-y", HF_Sphere(FV, 1, 0, <13, 7>, 0, "", <0, 0, 0>, 2, 1), <0, 0, 0>, array[3] { x, vnormalize(<1, 1, 0>), vnormalize(<1, -1, 0>) }, 2)
Dist("HF_Sphere not UV, F = x", HF_Sphere(FU, 0, 0, <13, 7>, 0, "", <1, 0, 0>, 2, 1), <1, 0, 0>, array[3] { x, -x, z }, 2)
Show("HF_Cylinder 0", HF_Cylinder(function { 0 }, 1, 0, <8, 8>, 0, "", <0, 0, 0>, <0, 3, 0>, 2, 0.5))
Show("HF_Cylinder 1", HF_Cylinder(function { 1 }, 1, 0, <9, 5>, 0, "", <0, 0, 0>, <0, 3, 0>, 2, 0.5))
Show("HF_Cylinder 1 along z", HF_Cylinder(function { 1 }, 1, 0, <9, 5>, 0, "", <1, 1, 1>, <1, 1, 4>, 2, 0.5))
Show("HF_Cylinder 0 oblique", HF_Cylinder(function { 0 }, 1, 0, <7, 4>, 0, "", <1, 0, -1>, <2, 3, 1>, 1, 0.5))
Dist("HF_Cylinder y: u at +x -x -z", HF_Cylinder(FU, 1, 0, <13, 7>, 0, "", <0, 0, 0>, <0, 3, 0>, 2, 1), <0, 1.5, 0>, array[3] { x, -x, -z }, 2)
Dist("HF_Cylinder z: u at +x -x -y", HF_Cylinder(FU, 1, 0, <13, 7>, 0, "", <0, 0, 0>, <0, 0, 3>, 2, 1), <0, 0, 1.5>, array[3] { x, -x, -y }, 2)
Dist("HF_Cylinder x: u at +y -y -z", HF_Cylinder(FU, 1, 0, <13, 7>, 0, "", <0, 0, 0>, <3, 0, 0>, 2, 1), <1.5, 0, 0>, array[3] { y, -y, -z }, 2)
Dist("HF_Cylinder -y: u at +x -x -z", HF_Cylinder(FU, 1, 0, <13, 7>, 0, "", <0, 0, 0>, <0, -3, 0>, 2, 1), <0, -1.5, 0>, array[3] { x, -x, -z }, 2)
Dist("HF_Cylinder y: v at y = 0.5", HF_Cylinder(FV, 1, 0, <13, 7>, 0, "", <0, 0, 0>, <0, 3, 0>, 2, 1), <0, 0.5, 0>, array[1] { x }, 2)
Dist("HF_Cylinder not UV, F = x", HF_Cylinder(FU, 0, 0, <13, 7>, 0, "", <1, 0, 0>, <1, 3, 0>, 2, 1), <1, 1.5, 0>, array[3] { x, -x, z }, 2)
Show("HF_Torus 0", HF_Torus(function { 0 }, 1, 0, <8, 8>, 0, "", 3, 1, 0.5))
Show("HF_Torus 1", HF_Torus(function { 1 }, 1, 0, <9, 9>, 0, "", 3, 1, 0.5))
Dist("HF_Torus u at +z -x -z", HF_Torus(FU, 1, 0, <13, 13>, 0, "", 3, 1, 1), <0, 0, 0>, array[3] { z, -x, -z }, 4)
Dist("HF_Torus v at the ring's +x: +x +y -y", HF_Torus(FV, 1, 0, <13, 13>, 0, "", 3, 1, 1), <3, 0, 0>, array[3] { x, y, -y }, 1)
Dist("HF_Torus not UV, F = x: +x +y", HF_Torus(FU, 0, 0, <13, 13>, 0, "", 3, 1, 1), <3, 0, 0>, array[2] { x, y }, 1)

// With a file name the macro writes the mesh to the file and makes
// nothing; the file is read back with #include.
HF_Torus(function { 0.5 }, 1, 1, <8, 6>, 0, "stdlib-shapes-3-torus.tmp", 3, 1, 0.5)
#declare H = object { #include "stdlib-shapes-3-torus.tmp" }
Show("HF_Torus written to a file", H)
