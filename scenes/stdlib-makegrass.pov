// stdlib-makegrass: makegrass.inc's macros. In front, one large folded and
// smooth blade (MakeBlade) beside a flat one; behind, a prairie
// (MakePrairie) of a patch of 5 x 5 blades (MakeGrassPatch), in rows that
// widen away from the camera. POV-Ray renders the reference with its own
// makegrass.inc; the meshes are the same, so the renders should agree.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "makegrass.inc"
camera { location <0, 1.4, -4.5> look_at <0, 0.6, 1> angle 50 }
background { rgb <0.55, 0.7, 0.95> }
light_source { <-6, 10, -8> rgb 1 }
light_source { <6, 4, -6> rgb 0.3 shadowless }
plane { y, 0 pigment { rgb <0.35, 0.25, 0.15> } }
#declare T_Blade = texture {
	pigment { gradient y color_map { [0 rgb <0.15, 0.35, 0.05>] [1 rgb <0.6, 0.8, 0.2>] } scale 1.2 }
	finish { diffuse 0.8 specular 0.3 roughness 0.02 }
}
// The blades, 1.2 units tall.
mesh {
	MakeBlade(1, <-0.8, 0, -2>, -30, 6, 1, 0.12, 0.02, 0.06, <0, 1, 0.3>, <0, 0.3, 1.2>, 2, 1, 0)
	texture { T_Blade }
}
mesh {
	MakeBlade(0, <-0.3, 0, -2.2>, 20, 6, 1, 0.12, 0.02, 0, <0, 1, 0.1>, <0.5, 0, 0.8>, 3, 0, 0)
	texture { T_Blade }
}
// The prairie.
#declare Patch = MakeGrassPatch(1, 5, 0, 4, 0.5, 0.03, 0.01, 0, <0, 1, 0.3>, <0, -0.3, 0>, 3, 459, 1, 360, 1.2, 2, 1, 0, "")
object {
	MakePrairie(1, 3, 1, 4, Patch, 17, 0.3, 1, 0)
	texture { T_Blade }
	translate <0, 0, -0.8>
}
