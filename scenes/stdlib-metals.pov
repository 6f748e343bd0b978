// stdlib-metals.pov: swatches of metals.inc, every texture on a sphere.
// Grid order (10 columns, 10 rows, read left to right, top to bottom): each
// row holds two pigment numbers with the five finishes A to E each:
//   row 1  T_Brass_1A .. T_Brass_1E, T_Brass_2A .. T_Brass_2E
//   row 2  Brass 3, 4;  row 3  Brass 5, Copper 1;  row 4  Copper 2, 3
//   row 5  Copper 4, 5;  row 6  Chrome 1, 2;  row 7  Chrome 3, 4
//   row 8  Chrome 5, Silver 1;  row 9  Silver 2, 3;  row 10  Silver 4, 5
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that the reflections show (a far camera with a narrow view, nearly
// orthographic).
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

// Swatch(I, Body): a sphere in cell I (from 0, left to right, then top to
// bottom) with the given texture, pigment or material statements.
#macro Swatch(I)
	sphere { <mod(I, Cols) - (Cols - 1) / 2, (Rows - 1) / 2 - div(I, Cols), 0>, 0.44
#end

Swatch(0) texture { T_Brass_1A } }
Swatch(1) texture { T_Brass_1B } }
Swatch(2) texture { T_Brass_1C } }
Swatch(3) texture { T_Brass_1D } }
Swatch(4) texture { T_Brass_1E } }
Swatch(5) texture { T_Brass_2A } }
Swatch(6) texture { T_Brass_2B } }
Swatch(7) texture { T_Brass_2C } }
Swatch(8) texture { T_Brass_2D } }
Swatch(9) texture { T_Brass_2E } }
Swatch(10) texture { T_Brass_3A } }
Swatch(11) texture { T_Brass_3B } }
Swatch(12) texture { T_Brass_3C } }
Swatch(13) texture { T_Brass_3D } }
Swatch(14) texture { T_Brass_3E } }
Swatch(15) texture { T_Brass_4A } }
Swatch(16) texture { T_Brass_4B } }
Swatch(17) texture { T_Brass_4C } }
Swatch(18) texture { T_Brass_4D } }
Swatch(19) texture { T_Brass_4E } }
Swatch(20) texture { T_Brass_5A } }
Swatch(21) texture { T_Brass_5B } }
Swatch(22) texture { T_Brass_5C } }
Swatch(23) texture { T_Brass_5D } }
Swatch(24) texture { T_Brass_5E } }
Swatch(25) texture { T_Copper_1A } }
Swatch(26) texture { T_Copper_1B } }
Swatch(27) texture { T_Copper_1C } }
Swatch(28) texture { T_Copper_1D } }
Swatch(29) texture { T_Copper_1E } }
Swatch(30) texture { T_Copper_2A } }
Swatch(31) texture { T_Copper_2B } }
Swatch(32) texture { T_Copper_2C } }
Swatch(33) texture { T_Copper_2D } }
Swatch(34) texture { T_Copper_2E } }
Swatch(35) texture { T_Copper_3A } }
Swatch(36) texture { T_Copper_3B } }
Swatch(37) texture { T_Copper_3C } }
Swatch(38) texture { T_Copper_3D } }
Swatch(39) texture { T_Copper_3E } }
Swatch(40) texture { T_Copper_4A } }
Swatch(41) texture { T_Copper_4B } }
Swatch(42) texture { T_Copper_4C } }
Swatch(43) texture { T_Copper_4D } }
Swatch(44) texture { T_Copper_4E } }
Swatch(45) texture { T_Copper_5A } }
Swatch(46) texture { T_Copper_5B } }
Swatch(47) texture { T_Copper_5C } }
Swatch(48) texture { T_Copper_5D } }
Swatch(49) texture { T_Copper_5E } }
Swatch(50) texture { T_Chrome_1A } }
Swatch(51) texture { T_Chrome_1B } }
Swatch(52) texture { T_Chrome_1C } }
Swatch(53) texture { T_Chrome_1D } }
Swatch(54) texture { T_Chrome_1E } }
Swatch(55) texture { T_Chrome_2A } }
Swatch(56) texture { T_Chrome_2B } }
Swatch(57) texture { T_Chrome_2C } }
Swatch(58) texture { T_Chrome_2D } }
Swatch(59) texture { T_Chrome_2E } }
Swatch(60) texture { T_Chrome_3A } }
Swatch(61) texture { T_Chrome_3B } }
Swatch(62) texture { T_Chrome_3C } }
Swatch(63) texture { T_Chrome_3D } }
Swatch(64) texture { T_Chrome_3E } }
Swatch(65) texture { T_Chrome_4A } }
Swatch(66) texture { T_Chrome_4B } }
Swatch(67) texture { T_Chrome_4C } }
Swatch(68) texture { T_Chrome_4D } }
Swatch(69) texture { T_Chrome_4E } }
Swatch(70) texture { T_Chrome_5A } }
Swatch(71) texture { T_Chrome_5B } }
Swatch(72) texture { T_Chrome_5C } }
Swatch(73) texture { T_Chrome_5D } }
Swatch(74) texture { T_Chrome_5E } }
Swatch(75) texture { T_Silver_1A } }
Swatch(76) texture { T_Silver_1B } }
Swatch(77) texture { T_Silver_1C } }
Swatch(78) texture { T_Silver_1D } }
Swatch(79) texture { T_Silver_1E } }
Swatch(80) texture { T_Silver_2A } }
Swatch(81) texture { T_Silver_2B } }
Swatch(82) texture { T_Silver_2C } }
Swatch(83) texture { T_Silver_2D } }
Swatch(84) texture { T_Silver_2E } }
Swatch(85) texture { T_Silver_3A } }
Swatch(86) texture { T_Silver_3B } }
Swatch(87) texture { T_Silver_3C } }
Swatch(88) texture { T_Silver_3D } }
Swatch(89) texture { T_Silver_3E } }
Swatch(90) texture { T_Silver_4A } }
Swatch(91) texture { T_Silver_4B } }
Swatch(92) texture { T_Silver_4C } }
Swatch(93) texture { T_Silver_4D } }
Swatch(94) texture { T_Silver_4E } }
Swatch(95) texture { T_Silver_5A } }
Swatch(96) texture { T_Silver_5B } }
Swatch(97) texture { T_Silver_5C } }
Swatch(98) texture { T_Silver_5D } }
Swatch(99) texture { T_Silver_5E } }
