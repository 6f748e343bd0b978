// stdlib-old-stage1.pov: stage1.inc's camera, light and chequered backdrop,
// with the shapes of shapes_old.inc before it, in four rows of six, left to
// right: Sphere, Ellipsoid, Cone_X, Cone_Y, Cone_Z, UnitBox; Cube, Disk_X,
// Disk_Y, Disk_Z, Cylinder_X, Cylinder_Y; Cylinder_Z, QCone_X, QCone_Y,
// QCone_Z, Paraboloid_X, Paraboloid_Y; Paraboloid_Z, Hyperboloid,
// Hyperboloid_Y, Plane_YZ, Plane_XZ, Plane_XY. The infinite shapes are cut
// to the unit box, the planes to a thin slab of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "stage1.inc"
#include "shapes_old.inc"

// Show(O, I, Cut, Colour): O in cell I, cut to the unit box if Cut is 1 or
// to a slab of it 0.1 thick if Cut is 2, turned a little to show its depth.
#macro Show(O, I, Cut, Colour)
	#switch (Cut)
	#case (0) object { O #break
	#case (1) intersection { object { O } box { -1, 1 } #break
	#case (2) intersection { object { O } object { O scale -1 translate 0.1 * <1, 1, 1> inverse } box { -1, 1 } #break
	#end
		pigment { color Colour } finish { phong 0.5 }
		rotate <-25, 30, 0> scale 0.42 translate <-3.25 + mod(I, 6) * 1.3, 2.2 - div(I, 6) * 1.45, 0>
	}
#end
Show(Sphere, 0, 0, Red)
Show(Ellipsoid, 1, 0, Orange)
Show(Cone_X, 2, 0, Yellow)
Show(Cone_Y, 3, 0, Green)
Show(Cone_Z, 4, 0, Cyan)
Show(UnitBox, 5, 0, Blue)
Show(Cube, 6, 0, Magenta)
Show(Disk_X, 7, 0, Red)
Show(Disk_Y, 8, 0, Orange)
Show(Disk_Z, 9, 0, Yellow)
Show(Cylinder_X, 10, 1, Green)
Show(Cylinder_Y, 11, 1, Cyan)
Show(Cylinder_Z, 12, 1, Blue)
Show(QCone_X, 13, 1, Magenta)
Show(QCone_Y, 14, 1, Red)
Show(QCone_Z, 15, 1, Orange)
Show(Paraboloid_X, 16, 1, Yellow)
Show(Paraboloid_Y, 17, 1, Green)
Show(Paraboloid_Z, 18, 1, Cyan)
Show(Hyperboloid, 19, 1, Blue)
Show(Hyperboloid_Y, 20, 1, Magenta)
Show(Plane_YZ, 21, 2, Red)
Show(Plane_XZ, 22, 2, Green)
Show(Plane_XY, 23, 2, Blue)
