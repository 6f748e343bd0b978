// stdlib-old-shapes.pov: shapes_old.inc on its own: every predefined shape
// the manual lists, shown by the points where rays from outside meet it (and
// the normals there), whether sample points lie inside it, and, for the
// finite ones, its extents.
#version 3.7;
#include "shapes_old.inc"
// Rnd(V): V rounded to 5 decimals (no -0 from tiny paddings or rounding).
#macro Rnd(V) (<floor(V.x * 1e5 + 0.5), floor(V.y * 1e5 + 0.5), floor(V.z * 1e5 + 0.5)> / 1e5) #end
// Hit(Name, O, From, Dir): the first point where the ray From + t Dir meets
// O and the normal there, or "miss".
#macro Hit(Name, O, From, Dir)
	#local N = <0, 0, 0>;
	#local P = trace(O, From, Dir, N);
	#if (vlength(N) > 0)
		#debug concat(Name, " hit ", vstr(3, Rnd(P), ", ", 0, 5), " normal ", vstr(3, Rnd(N), ", ", 0, 5), "\n")
	#else
		#debug concat(Name, " miss\n")
	#end
#end
// Inside(Name, O, Pts): which of the points of the array Pts lie inside O.
#macro Inside(Name, O, Pts)
	#local S = "";
	#for (I, 0, dimension_size(Pts, 1) - 1)
		#local S = concat(S, str(inside(O, Pts[I]), 0, 0));
	#end
	#debug concat(Name, " inside ", S, "\n")
#end
#macro Ext(Name, O)
	#debug concat(Name, " extents ", vstr(3, Rnd(min_extent(O)), ", ", 0, 5), " / ", vstr(3, Rnd(max_extent(O)), ", ", 0, 5), "\n")
#end
// No point lies on a surface: whether those count as inside is the
// objects' business, not this file's.
#declare Pts = array[10] { <0.1, 0.2, -0.15>, <0.5, 0.5, 0.5>, <0.9, 0.05, -0.1>, <-0.1, 0.9, 0.05>,
	<0.05, -0.1, 0.9>, <3, 0.5, 0.2>, <0.5, 3, -0.2>, <0.2, -0.5, 3>, <2, -1, 1.5>, <-2, -0.5, -1> }
#macro Shape(Name, O, Finite)
	Hit(Name, O, <-5, 0.3, 0.2>, x)
	Hit(Name, O, <0.2, 5, 0.3>, -y)
	Hit(Name, O, <0.3, 0.2, -5>, z)
	Hit(Name, O, <4, 3, -5>, <-4, -3, 5.3>)
	Inside(Name, O, Pts)
	#if (Finite) Ext(Name, O) #end
#end
Shape("Ellipsoid", Ellipsoid, 1)
Shape("Sphere", Sphere, 1)
Shape("Cylinder_X", Cylinder_X, 0)
Shape("Cylinder_Y", Cylinder_Y, 0)
Shape("Cylinder_Z", Cylinder_Z, 0)
Shape("QCone_X", QCone_X, 0)
Shape("QCone_Y", QCone_Y, 0)
Shape("QCone_Z", QCone_Z, 0)
Shape("Cone_X", Cone_X, 1)
Shape("Cone_Y", Cone_Y, 1)
Shape("Cone_Z", Cone_Z, 1)
Shape("Plane_YZ", Plane_YZ, 0)
Shape("Plane_XZ", Plane_XZ, 0)
Shape("Plane_XY", Plane_XY, 0)
Shape("Paraboloid_X", Paraboloid_X, 0)
Shape("Paraboloid_Y", Paraboloid_Y, 0)
Shape("Paraboloid_Z", Paraboloid_Z, 0)
Shape("Hyperboloid", Hyperboloid, 0)
Shape("Hyperboloid_Y", Hyperboloid_Y, 0)
Shape("UnitBox", UnitBox, 1)
Shape("Cube", Cube, 1)
Shape("Disk_X", Disk_X, 1)
Shape("Disk_Y", Disk_Y, 1)
Shape("Disk_Z", Disk_Z, 1)
