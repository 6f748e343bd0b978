// stdlib-skies.pov: swatches of skies.inc. The sky is the sky_sphere
// S_Cloud<Sky> (Sky = 1 unless the including scene declares it: see
// stdlib-skies-2.pov .. -5.pov, which show the other four skies alone, with
// Swatches = false). The camera looks at the horizon, so the upper half of
// the image is sky. The lower half holds two rows of swatches before a
// grey backdrop, left to right:
//   top row:    P_Cloud1, P_Cloud2, P_Cloud3, P_Cloud4 (each glowing on a
//               unit sphere, as they look in the sky), O_Cloud1 (scaled down);
//   bottom row: T_Cloud1, T_Cloud2, T_Cloud3 (on unit spheres), O_Cloud2
//               (its two planes scaled down, turned to face the camera and
//               clipped by a sphere).
// POV-Ray's skies.inc needs colors.inc included first; lucent's includes
// what it needs.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "skies.inc"

#ifndef (Sky) #declare Sky = 1; #end
#ifndef (Swatches) #declare Swatches = true; #end

camera { location 0 direction 0.75 * z right x * 4 / 3 up y }
light_source { <-3000, 5000, -4000> color rgb 1 }
#switch (Sky)
#case (1) sky_sphere { S_Cloud1 } #break
#case (2) sky_sphere { S_Cloud2 } #break
#case (3) sky_sphere { S_Cloud3 } #break
#case (4) sky_sphere { S_Cloud4 } #break
#case (5) sky_sphere { S_Cloud5 } #break
#end

#if (Swatches)
	box { <-20, -20, 14>, <20, -0.1, 15> pigment { checker rgb 0.55 rgb 0.35 } finish { ambient 0.4 diffuse 0.6 } }
	// Cell(Col, Row): the centre of a swatch, 10 units away.
	#macro Cell(Col, Row) <(Col - 2) * 3.4, -1.75 - Row * 3.3, 10> #end
	#declare Glow = finish { ambient 1 diffuse 0 }
	sphere { 0, 1 pigment { P_Cloud1 } finish { Glow } scale 1.4 translate Cell(0, 0) }
	sphere { 0, 1 pigment { P_Cloud2 } finish { Glow } scale 1.4 translate Cell(1, 0) }
	sphere { 0, 1 pigment { P_Cloud3 } finish { Glow } scale 1.4 translate Cell(2, 0) }
	sphere { 0, 1 pigment { P_Cloud4 } finish { Glow } scale 1.4 translate Cell(3, 0) }
	object { O_Cloud1 scale 1.4 / 10000 translate Cell(4, 0) }
	sphere { 0, 1 texture { T_Cloud1 } scale 1.4 translate Cell(0, 1) }
	sphere { 0, 1 texture { T_Cloud2 } scale 1.4 translate Cell(1, 1) }
	sphere { 0, 1 texture { T_Cloud3 } scale 1.4 translate Cell(2, 1) }
	object { O_Cloud2 scale 1 / 4000 rotate -90 * x clipped_by { sphere { 0, 1 } } scale 1.4 translate Cell(3, 1) }
#end
