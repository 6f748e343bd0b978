// stdlib-finish.pov: swatches of finish.inc, every finish on a red sphere.
// Grid order (4 columns, 2 rows, left to right, top to bottom):
//   Dull, Shiny, Glossy, Phong_Dull,
//   Phong_Shiny, Phong_Glossy, Luminous, Mirror.
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "finish.inc"

#declare Cols = 4;
#declare Rows = 2;
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

Swatch(0) pigment { rgb <0.85, 0.3, 0.2> } finish { Dull } translate Cell(0) }
Swatch(1) pigment { rgb <0.85, 0.3, 0.2> } finish { Shiny } translate Cell(1) }
Swatch(2) pigment { rgb <0.85, 0.3, 0.2> } finish { Glossy } translate Cell(2) }
Swatch(3) pigment { rgb <0.85, 0.3, 0.2> } finish { Phong_Dull } translate Cell(3) }
Swatch(4) pigment { rgb <0.85, 0.3, 0.2> } finish { Phong_Shiny } translate Cell(4) }
Swatch(5) pigment { rgb <0.85, 0.3, 0.2> } finish { Phong_Glossy } translate Cell(5) }
Swatch(6) pigment { rgb <0.85, 0.3, 0.2> } finish { Luminous } translate Cell(6) }
Swatch(7) pigment { rgb <0.85, 0.3, 0.2> } finish { Mirror } translate Cell(7) }
