// stdlib-logo.pov: logo.inc's three logos, left to right Povray_Logo,
// Povray_Logo_Prism and Povray_Logo_Bevel, seen a little from the right and
// above, coloured from red at the bottom to blue at the top.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "logo.inc"

camera { location <1, 1.2, -8> look_at <0, -0.05, 0> angle 40 right x * 4 / 3 }
light_source { <3, 4, -5> * 1000 color rgb 1.2 }
light_source { <-5, 1, -3> * 1000 color rgb 0.3 shadowless }
background { color rgb <1, 0.98, 0.93> }
plane { z, 0.6 pigment { color rgb <0.9, 0.88, 0.84> } }

#declare Logo_Texture = texture {
	pigment { gradient y scale 2 translate -y
		color_map { [0 color rgb <0.7, 0.28, 0.28>] [0.5 color rgb <0.28, 0.63, 0.28>] [1 color rgb <0.28, 0.28, 0.7>] } }
	finish { phong 0.6 phong_size 40 }
}
object { Povray_Logo texture { Logo_Texture } translate -1.6 * x }
object { Povray_Logo_Prism texture { Logo_Texture } }
object { Povray_Logo_Bevel texture { Logo_Texture } translate 1.6 * x }
