// stdlib-golds.pov: swatches of golds.inc, every texture on a sphere.
// Grid order (5 columns, 5 rows, read left to right, top to bottom): row N
// holds T_Gold_NA .. T_Gold_NE.
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
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

// Cell(I): the centre of cell I (from 0, left to right, then top to bottom).
#macro Cell(I) <mod(I, Cols) - (Cols - 1) / 2, (Rows - 1) / 2 - div(I, Cols), 0> #end
// Swatch(I) ... }: a sphere at the origin, with the materials that follow,
// moved to cell I by "translate Cell(I)" before the closing brace.
#macro Swatch(I) sphere { 0, 0.44 #end

Swatch(0) texture { T_Gold_1A } translate Cell(0) }
Swatch(1) texture { T_Gold_1B } translate Cell(1) }
Swatch(2) texture { T_Gold_1C } translate Cell(2) }
Swatch(3) texture { T_Gold_1D } translate Cell(3) }
Swatch(4) texture { T_Gold_1E } translate Cell(4) }
Swatch(5) texture { T_Gold_2A } translate Cell(5) }
Swatch(6) texture { T_Gold_2B } translate Cell(6) }
Swatch(7) texture { T_Gold_2C } translate Cell(7) }
Swatch(8) texture { T_Gold_2D } translate Cell(8) }
Swatch(9) texture { T_Gold_2E } translate Cell(9) }
Swatch(10) texture { T_Gold_3A } translate Cell(10) }
Swatch(11) texture { T_Gold_3B } translate Cell(11) }
Swatch(12) texture { T_Gold_3C } translate Cell(12) }
Swatch(13) texture { T_Gold_3D } translate Cell(13) }
Swatch(14) texture { T_Gold_3E } translate Cell(14) }
Swatch(15) texture { T_Gold_4A } translate Cell(15) }
Swatch(16) texture { T_Gold_4B } translate Cell(16) }
Swatch(17) texture { T_Gold_4C } translate Cell(17) }
Swatch(18) texture { T_Gold_4D } translate Cell(18) }
Swatch(19) texture { T_Gold_4E } translate Cell(19) }
Swatch(20) texture { T_Gold_5A } translate Cell(20) }
Swatch(21) texture { T_Gold_5B } translate Cell(21) }
Swatch(22) texture { T_Gold_5C } translate Cell(22) }
Swatch(23) texture { T_Gold_5D } translate Cell(23) }
Swatch(24) texture { T_Gold_5E } translate Cell(24) }
