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
// so that refraction and reflection show (a far camera with a narrow view,
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

// Swatch(I, Body): a sphere in cell I (from 0, left to right, then top to
// bottom) with the given texture, pigment or material statements.
#macro Swatch(I)
	sphere { <mod(I, Cols) - (Cols - 1) / 2, (Rows - 1) / 2 - div(I, Cols), 0>, 0.44
#end

Swatch(0) material { texture { pigment { Col_Glass_Beerbottle } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(1) material { texture { pigment { Col_Glass_Bluish } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(2) material { texture { pigment { Col_Glass_Clear } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(3) material { texture { pigment { Col_Glass_Dark_Green } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(4) material { texture { pigment { Col_Glass_General } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(5) material { texture { pigment { Col_Glass_Green } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(6) material { texture { pigment { Col_Glass_Old } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(7) material { texture { pigment { Col_Glass_Orange } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(8) material { texture { pigment { Col_Glass_Ruby } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(9) material { texture { pigment { Col_Glass_Vicksbottle } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(10) material { texture { pigment { Col_Glass_Winebottle } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(11) material { texture { pigment { Col_Glass_Yellow } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(12) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_01 } } }
Swatch(13) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_02 } } }
Swatch(14) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_03 } } }
Swatch(15) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_04 } } }
Swatch(16) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_05 } } }
Swatch(17) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_06 } } }
Swatch(18) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_07 } } }
Swatch(19) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_08 } } }
Swatch(20) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_09 } } }
Swatch(21) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_01 } } }
Swatch(22) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_02 } } }
Swatch(23) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_03 } } }
Swatch(24) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_04 } } }
Swatch(25) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_05 } } }
Swatch(26) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amethyst_06 } } }
Swatch(27) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_01 } } }
Swatch(28) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_02 } } }
Swatch(29) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_03 } } }
Swatch(30) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_04 } } }
Swatch(31) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Apatite_05 } } }
Swatch(32) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_01 } } }
Swatch(33) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_02 } } }
Swatch(34) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_03 } } }
Swatch(35) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_04 } } }
Swatch(36) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_05 } } }
Swatch(37) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Aquamarine_06 } } }
Swatch(38) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_01 } } }
Swatch(39) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_02 } } }
Swatch(40) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_03 } } }
Swatch(41) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Azurite_04 } } }
Swatch(42) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Beerbottle } } }
Swatch(43) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_01 } } }
Swatch(44) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_02 } } }
Swatch(45) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_03 } } }
Swatch(46) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Blue_04 } } }
Swatch(47) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Citrine_01 } } }
Swatch(48) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Dark_Green } } }
Swatch(49) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_01 } } }
Swatch(50) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_02 } } }
Swatch(51) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_03 } } }
Swatch(52) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_04 } } }
Swatch(53) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_05 } } }
Swatch(54) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_06 } } }
Swatch(55) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Emerald_07 } } }
Swatch(56) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_01 } } }
Swatch(57) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_02 } } }
Swatch(58) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_03 } } }
Swatch(59) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_04 } } }
Swatch(60) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_05 } } }
Swatch(61) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_06 } } }
Swatch(62) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_07 } } }
Swatch(63) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_08 } } }
Swatch(64) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Fluorite_09 } } }
Swatch(65) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green } } }
Swatch(66) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_01 } } }
Swatch(67) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_02 } } }
Swatch(68) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_03 } } }
Swatch(69) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Green_04 } } }
Swatch(70) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_01 } } }
Swatch(71) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_02 } } }
Swatch(72) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_03 } } }
Swatch(73) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_04 } } }
Swatch(74) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_05 } } }
Swatch(75) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Gypsum_06 } } }
Swatch(76) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Orange } } }
Swatch(77) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_01 } } }
Swatch(78) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_02 } } }
Swatch(79) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_03 } } }
Swatch(80) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Red_04 } } }
Swatch(81) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby } } }
Swatch(82) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_01 } } }
Swatch(83) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_02 } } }
Swatch(84) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_03 } } }
Swatch(85) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_04 } } }
Swatch(86) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Ruby_05 } } }
Swatch(87) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_01 } } }
Swatch(88) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_02 } } }
Swatch(89) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Sapphire_03 } } }
Swatch(90) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_01 } } }
Swatch(91) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_02 } } }
Swatch(92) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Topaz_03 } } }
Swatch(93) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_01 } } }
Swatch(94) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_02 } } }
Swatch(95) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_03 } } }
Swatch(96) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_04 } } }
Swatch(97) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_05 } } }
Swatch(98) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Tourmaline_06 } } }
Swatch(99) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Vicksbottle } } }
Swatch(100) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Winebottle } } }
Swatch(101) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow } } }
Swatch(102) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_01 } } }
Swatch(103) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_02 } } }
Swatch(104) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_03 } } }
Swatch(105) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Yellow_04 } } }
Swatch(106) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass1 } } interior { I_Glass } } }
Swatch(107) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass2 } } interior { I_Glass } } }
Swatch(108) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass3 } } interior { I_Glass } } }
Swatch(109) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass4 } } interior { I_Glass } } }
Swatch(110) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass5 } } interior { I_Glass } } }
Swatch(111) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass6 } } interior { I_Glass } } }
Swatch(112) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass7 } } interior { I_Glass } } }
Swatch(113) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass8 } } interior { I_Glass } } }
Swatch(114) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass9 } } interior { I_Glass } } }
Swatch(115) material { texture { pigment { rgbf <1, 1, 1, 0.95> } finish { F_Glass10 } } interior { I_Glass } } }
Swatch(116) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass1 fade_color Col_Amber_05 } } }
Swatch(117) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass2 fade_color Col_Amber_05 } } }
Swatch(118) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass3 fade_color Col_Amber_05 } } }
Swatch(119) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass4 fade_color Col_Amber_05 } } }
Swatch(120) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Sqr1 fade_color Col_Amber_05 } } }
Swatch(121) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp1 fade_color Col_Amber_05 } } }
Swatch(122) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp2 fade_color Col_Amber_05 } } }
Swatch(123) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Fade_Exp3 fade_color Col_Amber_05 } } }
Swatch(124) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Dispersion1 fade_color Col_Amber_05 } } }
Swatch(125) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Dispersion2 fade_color Col_Amber_05 } } }
Swatch(126) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Caustics1 fade_color Col_Amber_05 } } }
Swatch(127) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass_Caustics2 fade_color Col_Amber_05 } } }
Swatch(128) material { texture { pigment { rgbf <1, 1, 1, 0.97> } finish { F_Glass7 } } interior { I_Glass fade_color Col_Amber_05 } } }
Swatch(129) texture { T_Glass1 } interior { I_Glass } }
Swatch(130) texture { T_Glass2 } interior { I_Glass } }
Swatch(131) texture { T_Glass3 } interior { I_Glass } }
Swatch(132) texture { T_Glass4 } interior { I_Glass } }
Swatch(133) texture { T_Old_Glass } interior { I_Glass } }
Swatch(134) texture { T_Winebottle_Glass } interior { I_Glass } }
Swatch(135) texture { T_Beerbottle_Glass } interior { I_Glass } }
Swatch(136) texture { T_Ruby_Glass } interior { I_Glass } }
Swatch(137) texture { T_Green_Glass } interior { I_Glass } }
Swatch(138) texture { T_Dark_Green_Glass } interior { I_Glass } }
Swatch(139) texture { T_Yellow_Glass } interior { I_Glass } }
Swatch(140) texture { T_Orange_Glass } interior { I_Glass } }
Swatch(141) texture { T_Vicksbottle_Glass } interior { I_Glass } }
