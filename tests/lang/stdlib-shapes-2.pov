// stdlib-shapes-2.pov: shapes.inc's construction macros (wire boxes, round
// boxes, cylinders and cones, quads), shown through the extents of the
// objects they return.
#version 3.7;
#include "shapes.inc"
// Rnd(V): V rounded to 4 decimals, so that POV-Ray's padding of some
// bounding boxes by 1e-10 to 1e-8 (triangles, tori) prints as 0, not -0.
#macro Rnd(V) (<floor(V.x * 1e4 + 0.5), floor(V.y * 1e4 + 0.5), floor(V.z * 1e4 + 0.5)> / 1e4) #end
#macro Show(Name, O)
	#debug concat(Name, ": ", vstr(3, Rnd(min_extent(O)), ", ", 0, 4), " / ", vstr(3, Rnd(max_extent(O)), ", ", 0, 4), "\n")
#end
Show("Wire_Box", Wire_Box(<0, 0, 0>, <1, 2, 3>, 0.1, 0))
Show("Wire_Box_Union", Wire_Box_Union(<1, 2, 3>, <-1, -2, -3>, 0.2))
Show("Wire_Box_Merge", Wire_Box_Merge(<0, 0, 0>, <1, 1, 1>, 0.05))
Show("Round_Box", Round_Box(<0, 0, 0>, <1, 2, 3>, 0.1, 0))
Show("Round_Box_Union", Round_Box_Union(<1, 2, 3>, <-1, -2, -3>, 0.3))
Show("Round_Box_Merge", Round_Box_Merge(<0, 0, 0>, <1, 1, 1>, 0.25))
Show("Round_Cylinder", Round_Cylinder(<0, 0, 0>, <0, 2, 0>, 1, 0.2, 0))
Show("Round_Cylinder_Union", Round_Cylinder_Union(<0, -1, 0>, <0, 3, 0>, 0.5, 0.1))
Show("Round_Cylinder_Merge", Round_Cylinder_Merge(<1, 1, 1>, <1, 4, 1>, 2, 0.5))
Show("Round_Cone2", Round_Cone2(<0, 0, 0>, 1, <0, 3, 0>, 0.5, 0))
Show("Round_Cone2_Union", Round_Cone2_Union(<0, 0, 0>, 0.5, <4, 0, 0>, 1))
Show("Round_Cone2_Merge", Round_Cone2_Merge(<1, 2, 3>, 1, <1, 2, 6>, 1))
Show("Round_Cone3", Round_Cone3(<0, 0, 0>, 1, <0, 3, 0>, 0.5, 0))
Show("Round_Cone3_Union", Round_Cone3_Union(<0, 0, 0>, 1, <0, 2, 0>, 1))
Show("Quad", union { Quad(<0, 0, 0>, <1, 0, 0>, <1, 1, 0.5>, <0, 1, 0>) })
Show("Smooth_Quad", union { Smooth_Quad(<0, 0, 0>, -z, <2, 0, 0>, -z, <2, 1, 0>, -z, <0, 1, 1>, -z) })
