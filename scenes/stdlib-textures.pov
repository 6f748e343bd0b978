// stdlib-textures.pov: swatches of textures.inc: every pigment, texture, finish, interior and material on a sphere, and the pattern macros.
// Grid order (12 columns, 10 rows, left to right, top to bottom):
//   cells 0-30 pigments: Jade, Red_Marble, White_Marble, Blood_Marble, Blue_Agate,
//     Sapphire_Agate, Brown_Agate, Pink_Granite, Blue_Sky, Bright_Blue_Sky,
//     Blue_Sky2, Blue_Sky3, Blood_Sky, Apocalypse, Clouds, FBM_Clouds,
//     Cherry_Wood, Pine_Wood, Dark_Wood, Tan_Wood, White_Wood, Tom_Wood,
//     DMFWood1 .. DMFWood5, Candy_Cane, Peel, Y_Gradient, X_Gradient;
//   cells 31-86 textures: PinkAlabaster, Shadow_Clouds, DMFWood6, DMFLightOak,
//     DMFDarkOak, EMBWood1, Yellow_Pine, Rosewood, Sandalwood, Glass, Glass2,
//     Glass3, Green_Glass, NBglass, NBoldglass, NBwinebottle, NBbeerbottle,
//     Ruby_Glass, Dark_Green_Glass, Yellow_Glass, Orange_Glass,
//     Vicks_Bottle_Glass, Water, Chrome_, Brass_, Bronze_, Gold_, Silver_,
//     Copper_Metal, the same _Texture, Polished_Chrome, Polished_Brass,
//     New_Brass, Spun_Brass, Brushed_Aluminum, Silver1 .. Silver3,
//     Brass_Valley, Rust, Rusty_Iron, Soft_Silver, New_Penny, Tinny_Brass,
//     Gold_Nugget, Aluminum, Bright_Bronze, Cork, Lightning1, Lightning2,
//     Starfield;
//   cells 87-90 finishes: Glass_Finish (on clear glass), Metal, SilverFinish,
//     Metallic_Finish (on a brass colour); cell 91 Glass_Interior;
//   cells 92-105 materials: M_Glass, M_Glass2, M_Glass3, M_Green_Glass,
//     M_NB_Glass, M_NB_Old_Glass, M_NB_Winebottle_Glass, M_NB_Beerbottle_Glass,
//     M_Ruby_Glass,
//     M_Dark_Green_Glass, M_Yellow_Glass, M_Orange_Glass, M_Vicks_Bottle_Glass,
//     M_Water;
//   cells 106-109 pattern macros with a grey-to-red colour map:
//     Irregular_Bricks_Ptrn(0.05, 2, 0.5, 0.2), Tiles_Ptrn(), Hex_Tiles_Ptrn(),
//     Star_Ptrn(1, 5, 2).
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "textures.inc"

#declare Cols = 12;
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

Swatch(0) pigment { Jade } translate Cell(0) }
Swatch(1) pigment { Red_Marble } translate Cell(1) }
Swatch(2) pigment { White_Marble } translate Cell(2) }
Swatch(3) pigment { Blood_Marble } translate Cell(3) }
Swatch(4) pigment { Blue_Agate } translate Cell(4) }
Swatch(5) pigment { Sapphire_Agate } translate Cell(5) }
Swatch(6) pigment { Brown_Agate } translate Cell(6) }
Swatch(7) pigment { Pink_Granite } translate Cell(7) }
Swatch(8) pigment { Blue_Sky } translate Cell(8) }
Swatch(9) pigment { Bright_Blue_Sky } translate Cell(9) }
Swatch(10) pigment { Blue_Sky2 } translate Cell(10) }
Swatch(11) pigment { Blue_Sky3 } translate Cell(11) }
Swatch(12) pigment { Blood_Sky } translate Cell(12) }
Swatch(13) pigment { Apocalypse } translate Cell(13) }
Swatch(14) pigment { Clouds } translate Cell(14) }
Swatch(15) pigment { FBM_Clouds } translate Cell(15) }
Swatch(16) pigment { Cherry_Wood } translate Cell(16) }
Swatch(17) pigment { Pine_Wood } translate Cell(17) }
Swatch(18) pigment { Dark_Wood } translate Cell(18) }
Swatch(19) pigment { Tan_Wood } translate Cell(19) }
Swatch(20) pigment { White_Wood } translate Cell(20) }
Swatch(21) pigment { Tom_Wood } translate Cell(21) }
Swatch(22) pigment { DMFWood1 } translate Cell(22) }
Swatch(23) pigment { DMFWood2 } translate Cell(23) }
Swatch(24) pigment { DMFWood3 } translate Cell(24) }
Swatch(25) pigment { DMFWood4 } translate Cell(25) }
Swatch(26) pigment { DMFWood5 } translate Cell(26) }
Swatch(27) pigment { Candy_Cane } translate Cell(27) }
Swatch(28) pigment { Peel } translate Cell(28) }
Swatch(29) pigment { Y_Gradient } translate Cell(29) }
Swatch(30) pigment { X_Gradient } translate Cell(30) }
Swatch(31) texture { PinkAlabaster } translate Cell(31) }
Swatch(32) texture { Shadow_Clouds } translate Cell(32) }
Swatch(33) texture { DMFWood6 } translate Cell(33) }
Swatch(34) texture { DMFLightOak } translate Cell(34) }
Swatch(35) texture { DMFDarkOak } translate Cell(35) }
Swatch(36) texture { EMBWood1 } translate Cell(36) }
Swatch(37) texture { Yellow_Pine } translate Cell(37) }
Swatch(38) texture { Rosewood } translate Cell(38) }
Swatch(39) texture { Sandalwood } translate Cell(39) }
Swatch(40) texture { Glass } translate Cell(40) }
Swatch(41) texture { Glass2 } translate Cell(41) }
Swatch(42) texture { Glass3 } translate Cell(42) }
Swatch(43) texture { Green_Glass } translate Cell(43) }
Swatch(44) texture { NBglass } translate Cell(44) }
Swatch(45) texture { NBoldglass } translate Cell(45) }
Swatch(46) texture { NBwinebottle } translate Cell(46) }
Swatch(47) texture { NBbeerbottle } translate Cell(47) }
Swatch(48) texture { Ruby_Glass } translate Cell(48) }
Swatch(49) texture { Dark_Green_Glass } translate Cell(49) }
Swatch(50) texture { Yellow_Glass } translate Cell(50) }
Swatch(51) texture { Orange_Glass } translate Cell(51) }
Swatch(52) texture { Vicks_Bottle_Glass } translate Cell(52) }
Swatch(53) texture { Water } translate Cell(53) }
Swatch(54) texture { Chrome_Metal } translate Cell(54) }
Swatch(55) texture { Brass_Metal } translate Cell(55) }
Swatch(56) texture { Bronze_Metal } translate Cell(56) }
Swatch(57) texture { Gold_Metal } translate Cell(57) }
Swatch(58) texture { Silver_Metal } translate Cell(58) }
Swatch(59) texture { Copper_Metal } translate Cell(59) }
Swatch(60) texture { Chrome_Texture } translate Cell(60) }
Swatch(61) texture { Brass_Texture } translate Cell(61) }
Swatch(62) texture { Bronze_Texture } translate Cell(62) }
Swatch(63) texture { Gold_Texture } translate Cell(63) }
Swatch(64) texture { Silver_Texture } translate Cell(64) }
Swatch(65) texture { Copper_Texture } translate Cell(65) }
Swatch(66) texture { Polished_Chrome } translate Cell(66) }
Swatch(67) texture { Polished_Brass } translate Cell(67) }
Swatch(68) texture { New_Brass } translate Cell(68) }
Swatch(69) texture { Spun_Brass } translate Cell(69) }
Swatch(70) texture { Brushed_Aluminum } translate Cell(70) }
Swatch(71) texture { Silver1 } translate Cell(71) }
Swatch(72) texture { Silver2 } translate Cell(72) }
Swatch(73) texture { Silver3 } translate Cell(73) }
Swatch(74) texture { Brass_Valley } translate Cell(74) }
Swatch(75) texture { Rust } translate Cell(75) }
Swatch(76) texture { Rusty_Iron } translate Cell(76) }
Swatch(77) texture { Soft_Silver } translate Cell(77) }
Swatch(78) texture { New_Penny } translate Cell(78) }
Swatch(79) texture { Tinny_Brass } translate Cell(79) }
Swatch(80) texture { Gold_Nugget } translate Cell(80) }
Swatch(81) texture { Aluminum } translate Cell(81) }
Swatch(82) texture { Bright_Bronze } translate Cell(82) }
Swatch(83) texture { Cork } translate Cell(83) }
Swatch(84) texture { Lightning1 } translate Cell(84) }
Swatch(85) texture { Lightning2 } translate Cell(85) }
Swatch(86) texture { Starfield } translate Cell(86) }
Swatch(87) pigment { rgbf <1, 1, 1, 0.95> } finish { Glass_Finish } interior { ior 1.5 } translate Cell(87) }
Swatch(88) pigment { rgb <0.8, 0.6, 0.3> } finish { Metal } translate Cell(88) }
Swatch(89) pigment { rgb <0.8, 0.6, 0.3> } finish { SilverFinish } translate Cell(89) }
Swatch(90) pigment { rgb <0.8, 0.6, 0.3> } finish { Metallic_Finish } translate Cell(90) }
Swatch(91) pigment { rgbf <1, 1, 1, 0.95> } finish { Glass_Finish } interior { Glass_Interior } translate Cell(91) }
Swatch(92) material { M_Glass } translate Cell(92) }
Swatch(93) material { M_Glass2 } translate Cell(93) }
Swatch(94) material { M_Glass3 } translate Cell(94) }
Swatch(95) material { M_Green_Glass } translate Cell(95) }
Swatch(96) material { M_NB_Glass } translate Cell(96) }
Swatch(97) material { M_NB_Old_Glass } translate Cell(97) }
Swatch(98) material { M_NB_Winebottle_Glass } translate Cell(98) }
Swatch(99) material { M_NB_Beerbottle_Glass } translate Cell(99) }
Swatch(100) material { M_Ruby_Glass } translate Cell(100) }
Swatch(101) material { M_Dark_Green_Glass } translate Cell(101) }
Swatch(102) material { M_Yellow_Glass } translate Cell(102) }
Swatch(103) material { M_Orange_Glass } translate Cell(103) }
Swatch(104) material { M_Vicks_Bottle_Glass } translate Cell(104) }
Swatch(105) material { M_Water } translate Cell(105) }
Swatch(106) pigment { Irregular_Bricks_Ptrn(0.05, 2, 0.5, 0.2) color_map { [0 rgb <0.55, 0.5, 0.45>] [1 rgb <0.75, 0.2, 0.1>] } scale 0.12 } translate Cell(106) }
Swatch(107) pigment { Tiles_Ptrn() color_map { [0 rgb <0.55, 0.5, 0.45>] [1 rgb <0.75, 0.2, 0.1>] } scale 0.25 } translate Cell(107) }
Swatch(108) pigment { Hex_Tiles_Ptrn() color_map { [0 rgb <0.55, 0.5, 0.45>] [1 rgb <0.75, 0.2, 0.1>] } scale 0.1 } translate Cell(108) }
Swatch(109) pigment { Star_Ptrn(1, 5, 2) color_map { [0 rgb <0.55, 0.5, 0.45>] [1 rgb <0.75, 0.2, 0.1>] } scale 0.42 } translate Cell(109) }
