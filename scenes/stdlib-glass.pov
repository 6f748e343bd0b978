// stdlib-glass.pov: swatches of glass.inc: every colour, finish, interior and texture on a glass sphere.
// Grid order (12 columns, 12 rows, left to right, top to bottom):
//   cells 0-11: Col_Glass_Beerbottle, Bluish, Clear, Dark_Green, General, Green,
//     Old, Orange, Ruby, Vicksbottle, Winebottle, Yellow as the pigment
//     (finish F_Glass7, interior I_Glass);
//   cells 12-105: the 94 fade colours in the manual's (alphabetical) order,
//     Col_Amber_01 .. Col_Yellow_04, as fade_color of I_Glass3;
//   cells 106-115: F_Glass1 .. F_Glass10 on clear glass;
//   cells 116-128: I_Glass1 .. I_Glass4, I_Glass_Fade_Sqr1, I_Glass_Fade_Exp1 .. 3,
//     I_Glass_Dispersion1, 2, I_Glass_Caustics1, 2, I_Glass (fade_color Col_Amber_05);
//   cells 129-141: T_Glass1 .. T_Glass4, T_Old_Glass, T_Winebottle_Glass,
//     T_Beerbottle_Glass, T_Ruby_Glass, T_Green_Glass, T_Dark_Green_Glass,
//     T_Yellow_Glass, T_Orange_Glass, T_Vicksbottle_Glass (interior I_Glass).
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "glass.inc"

#declare Cols = 12;
#declare Rows = 12;
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

Swatch(0) material { texture { pigment { Col_Glass_Beerbottle } finish { F_Glass7 } } interior { I_Glass } } translate Cell(0) }
Swatch(1) material { texture { pigment { Col_Glass_Bluish } finish { F_Glass7 } } interior { I_Glass } } translate Cell(1) }
Swatch(2) material { texture { pigment { Col_Glass_Clear } finish { F_Glass7 } } interior { I_Glass } } translate Cell(2) }
Swatch(3) material { texture { pigment { Col_Glass_Dark_Green } finish { F_Glass7 } } interior { I_Glass } } translate Cell(3) }
Swatch(4) material { texture { pigment { Col_Glass_General } finish { F_Glass7 } } interior { I_Glass } } translate Cell(4) }
Swatch(5) material { texture { pigment { Col_Glass_Green } finish { F_Glass7 } } interior { I_Glass } } translate Cell(5) }
Swatch(6) material { texture { pigment { Col_Glass_Old } finish { F_Glass7 } } interior { I_Glass } } translate Cell(6) }
Swatch(7) material { texture { pigment { Col_Glass_Orange } finish { F_Glass7 } } interior { I_Glass } } translate Cell(7) }
Swatch(8) material { texture { pigment { Col_Glass_Ruby } finish { F_Glass7 } } interior { I_Glass } } translate Cell(8) }
Swatch(9) material { texture { pigment { Col_Glass_Vicksbottle } finish { F_Glass7 } } interior { I_Glass } } translate Cell(9) }
Swatch(10) material { texture { pigment { Col_Glass_Winebottle } finish { F_Glass7 } } interior { I_Glass } } translate Cell(10) }
Swatch(11) material { texture { pigment { Col_Glass_Yellow } finish { F_Glass7 } } interior { I_Glass } } translate Cell(11) }
Swatch(12) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_01 } } translate Cell(12) }
Swatch(13) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_02 } } translate Cell(13) }
Swatch(14) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_03 } } translate Cell(14) }
Swatch(15) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_04 } } translate Cell(15) }
Swatch(16) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_05 } } translate Cell(16) }
Swatch(17) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_06 } } translate Cell(17) }
Swatch(18) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_07 } } translate Cell(18) }
Swatch(19) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_08 } } translate Cell(19) }
Swatch(20) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_09 } } translate Cell(20) }
Swatch(21) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_01 } } translate Cell(21) }
Swatch(22) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_02 } } translate Cell(22) }
Swatch(23) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_03 } } translate Cell(23) }
Swatch(24) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_04 } } translate Cell(24) }
Swatch(25) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_05 } } translate Cell(25) }
Swatch(26) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_06 } } translate Cell(26) }
Swatch(27) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_01 } } translate Cell(27) }
Swatch(28) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_02 } } translate Cell(28) }
Swatch(29) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_03 } } translate Cell(29) }
Swatch(30) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_04 } } translate Cell(30) }
Swatch(31) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_05 } } translate Cell(31) }
Swatch(32) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_01 } } translate Cell(32) }
Swatch(33) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_02 } } translate Cell(33) }
Swatch(34) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_03 } } translate Cell(34) }
Swatch(35) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_04 } } translate Cell(35) }
Swatch(36) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_05 } } translate Cell(36) }
Swatch(37) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_06 } } translate Cell(37) }
Swatch(38) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_01 } } translate Cell(38) }
Swatch(39) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_02 } } translate Cell(39) }
Swatch(40) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_03 } } translate Cell(40) }
Swatch(41) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_04 } } translate Cell(41) }
Swatch(42) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Beerbottle } } translate Cell(42) }
Swatch(43) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_01 } } translate Cell(43) }
Swatch(44) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_02 } } translate Cell(44) }
Swatch(45) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_03 } } translate Cell(45) }
Swatch(46) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_04 } } translate Cell(46) }
Swatch(47) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Citrine_01 } } translate Cell(47) }
Swatch(48) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Dark_Green } } translate Cell(48) }
Swatch(49) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_01 } } translate Cell(49) }
Swatch(50) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_02 } } translate Cell(50) }
Swatch(51) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_03 } } translate Cell(51) }
Swatch(52) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_04 } } translate Cell(52) }
Swatch(53) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_05 } } translate Cell(53) }
Swatch(54) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_06 } } translate Cell(54) }
Swatch(55) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_07 } } translate Cell(55) }
Swatch(56) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_01 } } translate Cell(56) }
Swatch(57) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_02 } } translate Cell(57) }
Swatch(58) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_03 } } translate Cell(58) }
Swatch(59) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_04 } } translate Cell(59) }
Swatch(60) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_05 } } translate Cell(60) }
Swatch(61) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_06 } } translate Cell(61) }
Swatch(62) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_07 } } translate Cell(62) }
Swatch(63) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_08 } } translate Cell(63) }
Swatch(64) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_09 } } translate Cell(64) }
Swatch(65) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green } } translate Cell(65) }
Swatch(66) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_01 } } translate Cell(66) }
Swatch(67) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_02 } } translate Cell(67) }
Swatch(68) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_03 } } translate Cell(68) }
Swatch(69) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_04 } } translate Cell(69) }
Swatch(70) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_01 } } translate Cell(70) }
Swatch(71) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_02 } } translate Cell(71) }
Swatch(72) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_03 } } translate Cell(72) }
Swatch(73) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_04 } } translate Cell(73) }
Swatch(74) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_05 } } translate Cell(74) }
Swatch(75) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_06 } } translate Cell(75) }
Swatch(76) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Orange } } translate Cell(76) }
Swatch(77) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_01 } } translate Cell(77) }
Swatch(78) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_02 } } translate Cell(78) }
Swatch(79) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_03 } } translate Cell(79) }
Swatch(80) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_04 } } translate Cell(80) }
Swatch(81) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby } } translate Cell(81) }
Swatch(82) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_01 } } translate Cell(82) }
Swatch(83) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_02 } } translate Cell(83) }
Swatch(84) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_03 } } translate Cell(84) }
Swatch(85) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_04 } } translate Cell(85) }
Swatch(86) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_05 } } translate Cell(86) }
Swatch(87) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_01 } } translate Cell(87) }
Swatch(88) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_02 } } translate Cell(88) }
Swatch(89) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_03 } } translate Cell(89) }
Swatch(90) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_01 } } translate Cell(90) }
Swatch(91) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_02 } } translate Cell(91) }
Swatch(92) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_03 } } translate Cell(92) }
Swatch(93) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_01 } } translate Cell(93) }
Swatch(94) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_02 } } translate Cell(94) }
Swatch(95) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_03 } } translate Cell(95) }
Swatch(96) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_04 } } translate Cell(96) }
Swatch(97) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_05 } } translate Cell(97) }
Swatch(98) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_06 } } translate Cell(98) }
Swatch(99) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Vicksbottle } } translate Cell(99) }
Swatch(100) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Winebottle } } translate Cell(100) }
Swatch(101) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow } } translate Cell(101) }
Swatch(102) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_01 } } translate Cell(102) }
Swatch(103) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_02 } } translate Cell(103) }
Swatch(104) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_03 } } translate Cell(104) }
Swatch(105) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_04 } } translate Cell(105) }
Swatch(106) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass1 } } interior { I_Glass } } translate Cell(106) }
Swatch(107) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass2 } } interior { I_Glass } } translate Cell(107) }
Swatch(108) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass3 } } interior { I_Glass } } translate Cell(108) }
Swatch(109) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass4 } } interior { I_Glass } } translate Cell(109) }
Swatch(110) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass5 } } interior { I_Glass } } translate Cell(110) }
Swatch(111) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass6 } } interior { I_Glass } } translate Cell(111) }
Swatch(112) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass7 } } interior { I_Glass } } translate Cell(112) }
Swatch(113) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass8 } } interior { I_Glass } } translate Cell(113) }
Swatch(114) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass9 } } interior { I_Glass } } translate Cell(114) }
Swatch(115) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass10 } } interior { I_Glass } } translate Cell(115) }
Swatch(116) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass1 fade_color Col_Amber_05 } } translate Cell(116) }
Swatch(117) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass2 fade_color Col_Amber_05 } } translate Cell(117) }
Swatch(118) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_05 } } translate Cell(118) }
Swatch(119) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass4 fade_color Col_Amber_05 } } translate Cell(119) }
Swatch(120) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Sqr1 fade_color Col_Amber_05 } } translate Cell(120) }
Swatch(121) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp1 fade_color Col_Amber_05 } } translate Cell(121) }
Swatch(122) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp2 fade_color Col_Amber_05 } } translate Cell(122) }
Swatch(123) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp3 fade_color Col_Amber_05 } } translate Cell(123) }
Swatch(124) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Dispersion1 fade_color Col_Amber_05 } } translate Cell(124) }
Swatch(125) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Dispersion2 fade_color Col_Amber_05 } } translate Cell(125) }
Swatch(126) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Caustics1 fade_color Col_Amber_05 } } translate Cell(126) }
Swatch(127) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Caustics2 fade_color Col_Amber_05 } } translate Cell(127) }
Swatch(128) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass fade_color Col_Amber_05 } } translate Cell(128) }
Swatch(129) texture { T_Glass1 } interior { I_Glass } translate Cell(129) }
Swatch(130) texture { T_Glass2 } interior { I_Glass } translate Cell(130) }
Swatch(131) texture { T_Glass3 } interior { I_Glass } translate Cell(131) }
Swatch(132) texture { T_Glass4 } interior { I_Glass } translate Cell(132) }
Swatch(133) texture { T_Old_Glass } interior { I_Glass } translate Cell(133) }
Swatch(134) texture { T_Winebottle_Glass } interior { I_Glass } translate Cell(134) }
Swatch(135) texture { T_Beerbottle_Glass } interior { I_Glass } translate Cell(135) }
Swatch(136) texture { T_Ruby_Glass } interior { I_Glass } translate Cell(136) }
Swatch(137) texture { T_Green_Glass } interior { I_Glass } translate Cell(137) }
Swatch(138) texture { T_Dark_Green_Glass } interior { I_Glass } translate Cell(138) }
Swatch(139) texture { T_Yellow_Glass } interior { I_Glass } translate Cell(139) }
Swatch(140) texture { T_Orange_Glass } interior { I_Glass } translate Cell(140) }
Swatch(141) texture { T_Vicksbottle_Glass } interior { I_Glass } translate Cell(141) }
