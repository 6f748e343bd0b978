// stdlib-golds.pov: swatches of golds.inc, every texture on a sphere.
// Grid order (5 columns, 5 rows, read left to right, top to bottom): row N
// holds T_Gold_NA .. T_Gold_NE. The spheres stand before a checkered wall
// inside a sky-to-ground gradient so that the reflections show (a far
// camera with a narrow view, nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "golds.inc"

#declare Cols = 5;
#declare Rows = 5;
camera { location <0, 0, -200> direction <0, 0, 200> right x * Cols up y * Rows }
light_source { <-30, 40, -50> color rgb 1 }
light_source { <40, 10, -30> color rgb 0.3 shadowless }
sphere { 0, 1000 hollow no_shadow
	pigment { gradient y color_map { [0.49 rgb <0.3, 0.22, 0.15>] [0.51 rgb <0.8, 0.85, 0.9>] [0.7 rgb <0.3, 0.5, 0.9>] } scale 2000 translate -1000 * y }
	finish { ambient 1 diffuse 0 } }
plane { z, 1 pigment { checker rgb 0.85 rgb 0.25 scale 0.5 } finish { ambient 0.3 diffuse 0.6 } }

// Swatch(I, Body): a sphere in cell I (from 0, left to right, then top to
// bottom) with the given texture, pigment or material statements.
#macro Swatch(I)
	sphere { <mod(I, Cols) - (Cols - 1) / 2, (Rows - 1) / 2 - div(I, Cols), 0>, 0.44
#end

Swatch(0) texture { T_Gold_1A } }
Swatch(1) texture { T_Gold_1B } }
Swatch(2) texture { T_Gold_1C } }
Swatch(3) texture { T_Gold_1D } }
Swatch(4) texture { T_Gold_1E } }
Swatch(5) texture { T_Gold_2A } }
Swatch(6) texture { T_Gold_2B } }
Swatch(7) texture { T_Gold_2C } }
Swatch(8) texture { T_Gold_2D } }
Swatch(9) texture { T_Gold_2E } }
Swatch(10) texture { T_Gold_3A } }
Swatch(11) texture { T_Gold_3B } }
Swatch(12) texture { T_Gold_3C } }
Swatch(13) texture { T_Gold_3D } }
Swatch(14) texture { T_Gold_3E } }
Swatch(15) texture { T_Gold_4A } }
Swatch(16) texture { T_Gold_4B } }
Swatch(17) texture { T_Gold_4C } }
Swatch(18) texture { T_Gold_4D } }
Swatch(19) texture { T_Gold_4E } }
Swatch(20) texture { T_Gold_5A } }
Swatch(21) texture { T_Gold_5B } }
Swatch(22) texture { T_Gold_5C } }
Swatch(23) texture { T_Gold_5D } }
Swatch(24) texture { T_Gold_5E } }
