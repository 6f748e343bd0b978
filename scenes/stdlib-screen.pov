// stdlib-screen: screen.inc's camera, an object held in the upper left corner
// and a textured rectangle in the lower right, for a turned camera with a
// tilted sky (rendered by POV-Ray with its own screen.inc for the reference).
#version 3.7;
global_settings { assumed_gamma 1 }
#include "screen.inc"
Set_Camera(<1,2,-3>, <0,0.5,0>, 50)
Set_Camera_Sky(<0.2,1,0>)
background { rgb <0,0,0.3> }
light_source { <5,10,-5> rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.2 } }
sphere { <0,0.5,0>, 0.5 pigment { rgb <1,0.5,0> } }
Screen_Object(sphere { 0, 0.05 pigment { rgb <0,1,0> } finish { ambient 1 diffuse 0 } }, <0.1,0.9>, 0.02, true, 0.5)
Screen_Plane(texture { pigment { function { x } color_map { [0 rgb 0][1 rgb <1,0,0>] } } finish { ambient 1 diffuse 0 } }, 0.5, <0.6,0>, <1,0.2>)
