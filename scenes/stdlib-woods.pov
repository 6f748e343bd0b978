// stdlib-woods.pov: swatches of woods.inc and woodmaps.inc: every pigment with its colour map, and every texture, on a sphere.
// Grid order (10 columns, 8 rows, left to right, top to bottom):
//   cells 0-18: P_WoodGrain1A .. P_WoodGrain19A with M_Wood1A .. M_Wood19A;
//   cells 19-37: P_WoodGrain1B .. P_WoodGrain19B with M_Wood1B .. M_Wood19B,
//     over a light grey layer;
//   cells 38-72: T_Wood1 .. T_Wood35.
// Everything is turned by rotate <20, 50, 0> so that both the rings and the
// grain along the log (z) show.
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "woods.inc"

#declare Cols = 10;
#declare Rows = 8;
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

Swatch(0) pigment { P_WoodGrain1A color_map { M_Wood1A } rotate <20, 50, 0> } translate Cell(0) }
Swatch(1) pigment { P_WoodGrain2A color_map { M_Wood2A } rotate <20, 50, 0> } translate Cell(1) }
Swatch(2) pigment { P_WoodGrain3A color_map { M_Wood3A } rotate <20, 50, 0> } translate Cell(2) }
Swatch(3) pigment { P_WoodGrain4A color_map { M_Wood4A } rotate <20, 50, 0> } translate Cell(3) }
Swatch(4) pigment { P_WoodGrain5A color_map { M_Wood5A } rotate <20, 50, 0> } translate Cell(4) }
Swatch(5) pigment { P_WoodGrain6A color_map { M_Wood6A } rotate <20, 50, 0> } translate Cell(5) }
Swatch(6) pigment { P_WoodGrain7A color_map { M_Wood7A } rotate <20, 50, 0> } translate Cell(6) }
Swatch(7) pigment { P_WoodGrain8A color_map { M_Wood8A } rotate <20, 50, 0> } translate Cell(7) }
Swatch(8) pigment { P_WoodGrain9A color_map { M_Wood9A } rotate <20, 50, 0> } translate Cell(8) }
Swatch(9) pigment { P_WoodGrain10A color_map { M_Wood10A } rotate <20, 50, 0> } translate Cell(9) }
Swatch(10) pigment { P_WoodGrain11A color_map { M_Wood11A } rotate <20, 50, 0> } translate Cell(10) }
Swatch(11) pigment { P_WoodGrain12A color_map { M_Wood12A } rotate <20, 50, 0> } translate Cell(11) }
Swatch(12) pigment { P_WoodGrain13A color_map { M_Wood13A } rotate <20, 50, 0> } translate Cell(12) }
Swatch(13) pigment { P_WoodGrain14A color_map { M_Wood14A } rotate <20, 50, 0> } translate Cell(13) }
Swatch(14) pigment { P_WoodGrain15A color_map { M_Wood15A } rotate <20, 50, 0> } translate Cell(14) }
Swatch(15) pigment { P_WoodGrain16A color_map { M_Wood16A } rotate <20, 50, 0> } translate Cell(15) }
Swatch(16) pigment { P_WoodGrain17A color_map { M_Wood17A } rotate <20, 50, 0> } translate Cell(16) }
Swatch(17) pigment { P_WoodGrain18A color_map { M_Wood18A } rotate <20, 50, 0> } translate Cell(17) }
Swatch(18) pigment { P_WoodGrain19A color_map { M_Wood19A } rotate <20, 50, 0> } translate Cell(18) }
Swatch(19) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain1B color_map { M_Wood1B } rotate <20, 50, 0> } } translate Cell(19) }
Swatch(20) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain2B color_map { M_Wood2B } rotate <20, 50, 0> } } translate Cell(20) }
Swatch(21) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain3B color_map { M_Wood3B } rotate <20, 50, 0> } } translate Cell(21) }
Swatch(22) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain4B color_map { M_Wood4B } rotate <20, 50, 0> } } translate Cell(22) }
Swatch(23) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain5B color_map { M_Wood5B } rotate <20, 50, 0> } } translate Cell(23) }
Swatch(24) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain6B color_map { M_Wood6B } rotate <20, 50, 0> } } translate Cell(24) }
Swatch(25) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain7B color_map { M_Wood7B } rotate <20, 50, 0> } } translate Cell(25) }
Swatch(26) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain8B color_map { M_Wood8B } rotate <20, 50, 0> } } translate Cell(26) }
Swatch(27) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain9B color_map { M_Wood9B } rotate <20, 50, 0> } } translate Cell(27) }
Swatch(28) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain10B color_map { M_Wood10B } rotate <20, 50, 0> } } translate Cell(28) }
Swatch(29) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain11B color_map { M_Wood11B } rotate <20, 50, 0> } } translate Cell(29) }
Swatch(30) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain12B color_map { M_Wood12B } rotate <20, 50, 0> } } translate Cell(30) }
Swatch(31) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain13B color_map { M_Wood13B } rotate <20, 50, 0> } } translate Cell(31) }
Swatch(32) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain14B color_map { M_Wood14B } rotate <20, 50, 0> } } translate Cell(32) }
Swatch(33) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain15B color_map { M_Wood15B } rotate <20, 50, 0> } } translate Cell(33) }
Swatch(34) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain16B color_map { M_Wood16B } rotate <20, 50, 0> } } translate Cell(34) }
Swatch(35) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain17B color_map { M_Wood17B } rotate <20, 50, 0> } } translate Cell(35) }
Swatch(36) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain18B color_map { M_Wood18B } rotate <20, 50, 0> } } translate Cell(36) }
Swatch(37) texture { pigment { rgb 0.9 } } texture { pigment { P_WoodGrain19B color_map { M_Wood19B } rotate <20, 50, 0> } } translate Cell(37) }
Swatch(38) texture { T_Wood1 rotate <20, 50, 0> } translate Cell(38) }
Swatch(39) texture { T_Wood2 rotate <20, 50, 0> } translate Cell(39) }
Swatch(40) texture { T_Wood3 rotate <20, 50, 0> } translate Cell(40) }
Swatch(41) texture { T_Wood4 rotate <20, 50, 0> } translate Cell(41) }
Swatch(42) texture { T_Wood5 rotate <20, 50, 0> } translate Cell(42) }
Swatch(43) texture { T_Wood6 rotate <20, 50, 0> } translate Cell(43) }
Swatch(44) texture { T_Wood7 rotate <20, 50, 0> } translate Cell(44) }
Swatch(45) texture { T_Wood8 rotate <20, 50, 0> } translate Cell(45) }
Swatch(46) texture { T_Wood9 rotate <20, 50, 0> } translate Cell(46) }
Swatch(47) texture { T_Wood10 rotate <20, 50, 0> } translate Cell(47) }
Swatch(48) texture { T_Wood11 rotate <20, 50, 0> } translate Cell(48) }
Swatch(49) texture { T_Wood12 rotate <20, 50, 0> } translate Cell(49) }
Swatch(50) texture { T_Wood13 rotate <20, 50, 0> } translate Cell(50) }
Swatch(51) texture { T_Wood14 rotate <20, 50, 0> } translate Cell(51) }
Swatch(52) texture { T_Wood15 rotate <20, 50, 0> } translate Cell(52) }
Swatch(53) texture { T_Wood16 rotate <20, 50, 0> } translate Cell(53) }
Swatch(54) texture { T_Wood17 rotate <20, 50, 0> } translate Cell(54) }
Swatch(55) texture { T_Wood18 rotate <20, 50, 0> } translate Cell(55) }
Swatch(56) texture { T_Wood19 rotate <20, 50, 0> } translate Cell(56) }
Swatch(57) texture { T_Wood20 rotate <20, 50, 0> } translate Cell(57) }
Swatch(58) texture { T_Wood21 rotate <20, 50, 0> } translate Cell(58) }
Swatch(59) texture { T_Wood22 rotate <20, 50, 0> } translate Cell(59) }
Swatch(60) texture { T_Wood23 rotate <20, 50, 0> } translate Cell(60) }
Swatch(61) texture { T_Wood24 rotate <20, 50, 0> } translate Cell(61) }
Swatch(62) texture { T_Wood25 rotate <20, 50, 0> } translate Cell(62) }
Swatch(63) texture { T_Wood26 rotate <20, 50, 0> } translate Cell(63) }
Swatch(64) texture { T_Wood27 rotate <20, 50, 0> } translate Cell(64) }
Swatch(65) texture { T_Wood28 rotate <20, 50, 0> } translate Cell(65) }
Swatch(66) texture { T_Wood29 rotate <20, 50, 0> } translate Cell(66) }
Swatch(67) texture { T_Wood30 rotate <20, 50, 0> } translate Cell(67) }
Swatch(68) texture { T_Wood31 rotate <20, 50, 0> } translate Cell(68) }
Swatch(69) texture { T_Wood32 rotate <20, 50, 0> } translate Cell(69) }
Swatch(70) texture { T_Wood33 rotate <20, 50, 0> } translate Cell(70) }
Swatch(71) texture { T_Wood34 rotate <20, 50, 0> } translate Cell(71) }
Swatch(72) texture { T_Wood35 rotate <20, 50, 0> } translate Cell(72) }
