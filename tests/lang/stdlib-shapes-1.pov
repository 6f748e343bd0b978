// stdlib-shapes-1.pov: shapes.inc's predefined shapes and its query and
// placement macros (Isect, IsectN, Extents, Center_Object, Align_Object,
// Spheroid, Connect_Spheres), shown through their extents and the points
// they return.
#version 3.7;
#include "shapes.inc"
// Rnd(V): V rounded to 5 decimals, so that POV-Ray's padding of some
// bounding boxes by 1e-10 to 1e-8 (triangles, tori) prints as 0, not -0.
#macro Rnd(V) (<floor(V.x * 1e5 + 0.5), floor(V.y * 1e5 + 0.5), floor(V.z * 1e5 + 0.5)> / 1e5) #end
#macro Show(Name, O)
	#debug concat(Name, ": ", vstr(3, Rnd(min_extent(O)), ", ", 0, 5), " / ", vstr(3, Rnd(max_extent(O)), ", ", 0, 5), "\n")
#end
Show("Sphere", Sphere)
Show("Cone_X", Cone_X)
Show("Cone_Y", Cone_Y)
Show("Cone_Z", Cone_Z)
Show("UnitBox", UnitBox)
Show("Cube", Cube)
Show("Disk_X", Disk_X)
Show("Disk_Y", Disk_Y)
Show("Disk_Z", Disk_Z)
#debug concat("Align: ", str(Align_Left, 0, 0), " ", str(Align_Right, 0, 0), " ", str(Align_Center, 0, 0), "\n")
#declare Ball = sphere { <1, 2, 3>, 0.5 }
#declare P = <9, 9, 9>;
#declare N = <9, 9, 9>;
#declare Hit = Isect(<1, 2, -5>, z, Ball, P);
#debug concat("Isect hit ", str(Hit, 0, 0), " at ", vstr(3, P, ", ", 0, 5), "\n")
#declare Hit = Isect(<5, 2, -5>, z, Ball, P);
#debug concat("Isect miss ", str(Hit, 0, 0), " P unchanged ", vstr(3, P, ", ", 0, 5), "\n")
#declare Hit = IsectN(<1, 5, 3>, -y, Ball, P, N);
#debug concat("IsectN hit ", str(Hit, 0, 0), " at ", vstr(3, P, ", ", 0, 5), " normal ", vstr(3, N, ", ", 0, 5), "\n")
#declare Mn = 0;
#declare Mx = 0;
Extents(Ball, Mn, Mx)
#debug concat("Extents ", vstr(3, Mn, ", ", 0, 5), " / ", vstr(3, Mx, ", ", 0, 5), "\n")
#declare B = box { <1, 2, 3>, <2, 4, 7> }
Show("Center_Object x", Center_Object(B, x))
Show("Center_Object x+y+z", Center_Object(B, x + y + z))
Show("Align_Object -y", Align_Object(B, -y, 0))
Show("Align_Object x-z", Align_Object(B, x - z, <10, 10, 10>))
Show("Spheroid", Spheroid(<1, 2, 3>, <1, 2, 0.5>))
Show("Connect_Spheres", Connect_Spheres(<0, 0, 0>, 1, <0, 3, 0>, 0.5))
Show("Connect_Spheres x", Connect_Spheres(<1, 0, 0>, 0.5, <5, 0, 0>, 1))
