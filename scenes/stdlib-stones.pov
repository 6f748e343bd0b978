// stdlib-stones.pov: swatches of stones.inc (stones1.inc and stones2.inc): every texture on a sphere.
// Grid order (12 columns, 9 rows, left to right, top to bottom):
//   cells 0-29: T_Grnt0 .. T_Grnt29;
//   cells 30-54: T_Grnt0a .. T_Grnt24a and cells 55-58: T_Crack1 .. T_Crack4,
//     each over a dark blue-grey layer so that their transparency shows;
//   cells 59-102: T_Stone1 .. T_Stone44.
// colors.inc comes first because POV-Ray's stones need it.
// The spheres stand before a checkered wall inside a sky-to-ground gradient
// so that reflections and transparency show (a far camera with a narrow view,
// nearly orthographic).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "stones.inc"

#declare Cols = 12;
#declare Rows = 9;
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

Swatch(0) texture { T_Grnt0 } translate Cell(0) }
Swatch(1) texture { T_Grnt1 } translate Cell(1) }
Swatch(2) texture { T_Grnt2 } translate Cell(2) }
Swatch(3) texture { T_Grnt3 } translate Cell(3) }
Swatch(4) texture { T_Grnt4 } translate Cell(4) }
Swatch(5) texture { T_Grnt5 } translate Cell(5) }
Swatch(6) texture { T_Grnt6 } translate Cell(6) }
Swatch(7) texture { T_Grnt7 } translate Cell(7) }
Swatch(8) texture { T_Grnt8 } translate Cell(8) }
Swatch(9) texture { T_Grnt9 } translate Cell(9) }
Swatch(10) texture { T_Grnt10 } translate Cell(10) }
Swatch(11) texture { T_Grnt11 } translate Cell(11) }
Swatch(12) texture { T_Grnt12 } translate Cell(12) }
Swatch(13) texture { T_Grnt13 } translate Cell(13) }
Swatch(14) texture { T_Grnt14 } translate Cell(14) }
Swatch(15) texture { T_Grnt15 } translate Cell(15) }
Swatch(16) texture { T_Grnt16 } translate Cell(16) }
Swatch(17) texture { T_Grnt17 } translate Cell(17) }
Swatch(18) texture { T_Grnt18 } translate Cell(18) }
Swatch(19) texture { T_Grnt19 } translate Cell(19) }
Swatch(20) texture { T_Grnt20 } translate Cell(20) }
Swatch(21) texture { T_Grnt21 } translate Cell(21) }
Swatch(22) texture { T_Grnt22 } translate Cell(22) }
Swatch(23) texture { T_Grnt23 } translate Cell(23) }
Swatch(24) texture { T_Grnt24 } translate Cell(24) }
Swatch(25) texture { T_Grnt25 } translate Cell(25) }
Swatch(26) texture { T_Grnt26 } translate Cell(26) }
Swatch(27) texture { T_Grnt27 } translate Cell(27) }
Swatch(28) texture { T_Grnt28 } translate Cell(28) }
Swatch(29) texture { T_Grnt29 } translate Cell(29) }
Swatch(30) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt0a } translate Cell(30) }
Swatch(31) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt1a } translate Cell(31) }
Swatch(32) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt2a } translate Cell(32) }
Swatch(33) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt3a } translate Cell(33) }
Swatch(34) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt4a } translate Cell(34) }
Swatch(35) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt5a } translate Cell(35) }
Swatch(36) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt6a } translate Cell(36) }
Swatch(37) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt7a } translate Cell(37) }
Swatch(38) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt8a } translate Cell(38) }
Swatch(39) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt9a } translate Cell(39) }
Swatch(40) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt10a } translate Cell(40) }
Swatch(41) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt11a } translate Cell(41) }
Swatch(42) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt12a } translate Cell(42) }
Swatch(43) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt13a } translate Cell(43) }
Swatch(44) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt14a } translate Cell(44) }
Swatch(45) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt15a } translate Cell(45) }
Swatch(46) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt16a } translate Cell(46) }
Swatch(47) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt17a } translate Cell(47) }
Swatch(48) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt18a } translate Cell(48) }
Swatch(49) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt19a } translate Cell(49) }
Swatch(50) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt20a } translate Cell(50) }
Swatch(51) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt21a } translate Cell(51) }
Swatch(52) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt22a } translate Cell(52) }
Swatch(53) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt23a } translate Cell(53) }
Swatch(54) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Grnt24a } translate Cell(54) }
Swatch(55) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Crack1 } translate Cell(55) }
Swatch(56) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Crack2 } translate Cell(56) }
Swatch(57) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Crack3 } translate Cell(57) }
Swatch(58) texture { pigment { rgb <0.35, 0.4, 0.5> } } texture { T_Crack4 } translate Cell(58) }
Swatch(59) texture { T_Stone1 } translate Cell(59) }
Swatch(60) texture { T_Stone2 } translate Cell(60) }
Swatch(61) texture { T_Stone3 } translate Cell(61) }
Swatch(62) texture { T_Stone4 } translate Cell(62) }
Swatch(63) texture { T_Stone5 } translate Cell(63) }
Swatch(64) texture { T_Stone6 } translate Cell(64) }
Swatch(65) texture { T_Stone7 } translate Cell(65) }
Swatch(66) texture { T_Stone8 } translate Cell(66) }
Swatch(67) texture { T_Stone9 } translate Cell(67) }
Swatch(68) texture { T_Stone10 } translate Cell(68) }
Swatch(69) texture { T_Stone11 } translate Cell(69) }
Swatch(70) texture { T_Stone12 } translate Cell(70) }
Swatch(71) texture { T_Stone13 } translate Cell(71) }
Swatch(72) texture { T_Stone14 } translate Cell(72) }
Swatch(73) texture { T_Stone15 } translate Cell(73) }
Swatch(74) texture { T_Stone16 } translate Cell(74) }
Swatch(75) texture { T_Stone17 } translate Cell(75) }
Swatch(76) texture { T_Stone18 } translate Cell(76) }
Swatch(77) texture { T_Stone19 } translate Cell(77) }
Swatch(78) texture { T_Stone20 } translate Cell(78) }
Swatch(79) texture { T_Stone21 } translate Cell(79) }
Swatch(80) texture { T_Stone22 } translate Cell(80) }
Swatch(81) texture { T_Stone23 } translate Cell(81) }
Swatch(82) texture { T_Stone24 } translate Cell(82) }
Swatch(83) texture { T_Stone25 } translate Cell(83) }
Swatch(84) texture { T_Stone26 } translate Cell(84) }
Swatch(85) texture { T_Stone27 } translate Cell(85) }
Swatch(86) texture { T_Stone28 } translate Cell(86) }
Swatch(87) texture { T_Stone29 } translate Cell(87) }
Swatch(88) texture { T_Stone30 } translate Cell(88) }
Swatch(89) texture { T_Stone31 } translate Cell(89) }
Swatch(90) texture { T_Stone32 } translate Cell(90) }
Swatch(91) texture { T_Stone33 } translate Cell(91) }
Swatch(92) texture { T_Stone34 } translate Cell(92) }
Swatch(93) texture { T_Stone35 } translate Cell(93) }
Swatch(94) texture { T_Stone36 } translate Cell(94) }
Swatch(95) texture { T_Stone37 } translate Cell(95) }
Swatch(96) texture { T_Stone38 } translate Cell(96) }
Swatch(97) texture { T_Stone39 } translate Cell(97) }
Swatch(98) texture { T_Stone40 } translate Cell(98) }
Swatch(99) texture { T_Stone41 } translate Cell(99) }
Swatch(100) texture { T_Stone42 } translate Cell(100) }
Swatch(101) texture { T_Stone43 } translate Cell(101) }
Swatch(102) texture { T_Stone44 } translate Cell(102) }
