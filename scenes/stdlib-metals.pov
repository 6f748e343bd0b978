// stdlib-metals.pov: swatches of metals.inc, every texture on a sphere.
// Grid order (10 columns, 10 rows, read left to right, top to bottom): each
// row holds two pigment numbers with the five finishes A to E each:
//   row 1  T_Brass_1A .. T_Brass_1E, T_Brass_2A .. T_Brass_2E
//   row 2  Brass 3, 4;  row 3  Brass 5, Copper 1;  row 4  Copper 2, 3
//   row 5  Copper 4, 5;  row 6  Chrome 1, 2;  row 7  Chrome 3, 4
//   row 8  Chrome 5, Silver 1;  row 9  Silver 2, 3;  row 10  Silver 4, 5
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "metals.inc"

#declare Cols = 10;
#declare Rows = 10;
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

Swatch(0) texture { T_Brass_1A } translate Cell(0) }
Swatch(1) texture { T_Brass_1B } translate Cell(1) }
Swatch(2) texture { T_Brass_1C } translate Cell(2) }
Swatch(3) texture { T_Brass_1D } translate Cell(3) }
Swatch(4) texture { T_Brass_1E } translate Cell(4) }
Swatch(5) texture { T_Brass_2A } translate Cell(5) }
Swatch(6) texture { T_Brass_2B } translate Cell(6) }
Swatch(7) texture { T_Brass_2C } translate Cell(7) }
Swatch(8) texture { T_Brass_2D } translate Cell(8) }
Swatch(9) texture { T_Brass_2E } translate Cell(9) }
Swatch(10) texture { T_Brass_3A } translate Cell(10) }
Swatch(11) texture { T_Brass_3B } translate Cell(11) }
Swatch(12) texture { T_Brass_3C } translate Cell(12) }
Swatch(13) texture { T_Brass_3D } translate Cell(13) }
Swatch(14) texture { T_Brass_3E } translate Cell(14) }
Swatch(15) texture { T_Brass_4A } translate Cell(15) }
Swatch(16) texture { T_Brass_4B } translate Cell(16) }
Swatch(17) texture { T_Brass_4C } translate Cell(17) }
Swatch(18) texture { T_Brass_4D } translate Cell(18) }
Swatch(19) texture { T_Brass_4E } translate Cell(19) }
Swatch(20) texture { T_Brass_5A } translate Cell(20) }
Swatch(21) texture { T_Brass_5B } translate Cell(21) }
Swatch(22) texture { T_Brass_5C } translate Cell(22) }
Swatch(23) texture { T_Brass_5D } translate Cell(23) }
Swatch(24) texture { T_Brass_5E } translate Cell(24) }
Swatch(25) texture { T_Copper_1A } translate Cell(25) }
Swatch(26) texture { T_Copper_1B } translate Cell(26) }
Swatch(27) texture { T_Copper_1C } translate Cell(27) }
Swatch(28) texture { T_Copper_1D } translate Cell(28) }
Swatch(29) texture { T_Copper_1E } translate Cell(29) }
Swatch(30) texture { T_Copper_2A } translate Cell(30) }
Swatch(31) texture { T_Copper_2B } translate Cell(31) }
Swatch(32) texture { T_Copper_2C } translate Cell(32) }
Swatch(33) texture { T_Copper_2D } translate Cell(33) }
Swatch(34) texture { T_Copper_2E } translate Cell(34) }
Swatch(35) texture { T_Copper_3A } translate Cell(35) }
Swatch(36) texture { T_Copper_3B } translate Cell(36) }
Swatch(37) texture { T_Copper_3C } translate Cell(37) }
Swatch(38) texture { T_Copper_3D } translate Cell(38) }
Swatch(39) texture { T_Copper_3E } translate Cell(39) }
Swatch(40) texture { T_Copper_4A } translate Cell(40) }
Swatch(41) texture { T_Copper_4B } translate Cell(41) }
Swatch(42) texture { T_Copper_4C } translate Cell(42) }
Swatch(43) texture { T_Copper_4D } translate Cell(43) }
Swatch(44) texture { T_Copper_4E } translate Cell(44) }
Swatch(45) texture { T_Copper_5A } translate Cell(45) }
Swatch(46) texture { T_Copper_5B } translate Cell(46) }
Swatch(47) texture { T_Copper_5C } translate Cell(47) }
Swatch(48) texture { T_Copper_5D } translate Cell(48) }
Swatch(49) texture { T_Copper_5E } translate Cell(49) }
Swatch(50) texture { T_Chrome_1A } translate Cell(50) }
Swatch(51) texture { T_Chrome_1B } translate Cell(51) }
Swatch(52) texture { T_Chrome_1C } translate Cell(52) }
Swatch(53) texture { T_Chrome_1D } translate Cell(53) }
Swatch(54) texture { T_Chrome_1E } translate Cell(54) }
Swatch(55) texture { T_Chrome_2A } translate Cell(55) }
Swatch(56) texture { T_Chrome_2B } translate Cell(56) }
Swatch(57) texture { T_Chrome_2C } translate Cell(57) }
Swatch(58) texture { T_Chrome_2D } translate Cell(58) }
Swatch(59) texture { T_Chrome_2E } translate Cell(59) }
Swatch(60) texture { T_Chrome_3A } translate Cell(60) }
Swatch(61) texture { T_Chrome_3B } translate Cell(61) }
Swatch(62) texture { T_Chrome_3C } translate Cell(62) }
Swatch(63) texture { T_Chrome_3D } translate Cell(63) }
Swatch(64) texture { T_Chrome_3E } translate Cell(64) }
Swatch(65) texture { T_Chrome_4A } translate Cell(65) }
Swatch(66) texture { T_Chrome_4B } translate Cell(66) }
Swatch(67) texture { T_Chrome_4C } translate Cell(67) }
Swatch(68) texture { T_Chrome_4D } translate Cell(68) }
Swatch(69) texture { T_Chrome_4E } translate Cell(69) }
Swatch(70) texture { T_Chrome_5A } translate Cell(70) }
Swatch(71) texture { T_Chrome_5B } translate Cell(71) }
Swatch(72) texture { T_Chrome_5C } translate Cell(72) }
Swatch(73) texture { T_Chrome_5D } translate Cell(73) }
Swatch(74) texture { T_Chrome_5E } translate Cell(74) }
Swatch(75) texture { T_Silver_1A } translate Cell(75) }
Swatch(76) texture { T_Silver_1B } translate Cell(76) }
Swatch(77) texture { T_Silver_1C } translate Cell(77) }
Swatch(78) texture { T_Silver_1D } translate Cell(78) }
Swatch(79) texture { T_Silver_1E } translate Cell(79) }
Swatch(80) texture { T_Silver_2A } translate Cell(80) }
Swatch(81) texture { T_Silver_2B } translate Cell(81) }
Swatch(82) texture { T_Silver_2C } translate Cell(82) }
Swatch(83) texture { T_Silver_2D } translate Cell(83) }
Swatch(84) texture { T_Silver_2E } translate Cell(84) }
Swatch(85) texture { T_Silver_3A } translate Cell(85) }
Swatch(86) texture { T_Silver_3B } translate Cell(86) }
Swatch(87) texture { T_Silver_3C } translate Cell(87) }
Swatch(88) texture { T_Silver_3D } translate Cell(88) }
Swatch(89) texture { T_Silver_3E } translate Cell(89) }
Swatch(90) texture { T_Silver_4A } translate Cell(90) }
Swatch(91) texture { T_Silver_4B } translate Cell(91) }
Swatch(92) texture { T_Silver_4C } translate Cell(92) }
Swatch(93) texture { T_Silver_4D } translate Cell(93) }
Swatch(94) texture { T_Silver_4E } translate Cell(94) }
Swatch(95) texture { T_Silver_5A } translate Cell(95) }
Swatch(96) texture { T_Silver_5B } translate Cell(96) }
Swatch(97) texture { T_Silver_5C } translate Cell(97) }
Swatch(98) texture { T_Silver_5D } translate Cell(98) }
Swatch(99) texture { T_Silver_5E } translate Cell(99) }
