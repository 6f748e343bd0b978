// stdlib-maps.pov: the ten colour maps of the *.map files, each on a sphere
// (top row) and as a strip of the map itself from 0 (bottom) to 1 (top),
// lit by nothing but its own ambient light (bottom row). Columns, left to
// right: M_Ash (ash.map), M_Benediti (benediti.map), M_Bubinga
// (bubinga.map), M_Cedar (cedar.map), M_Orangewood (orngwood.map), M_Teak
// (teak.map), M_WhiteAsh (whiteash.map) in wood; M_MarbTeal (marbteal.map)
// and M_PinkMarb (pinkmarb.map) in agate; M_RedGranite (rdgranit.map) in
// granite.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "ash.map"
#include "benediti.map"
#include "bubinga.map"
#include "cedar.map"
#include "marbteal.map"
#include "orngwood.map"
#include "pinkmarb.map"
#include "rdgranit.map"
#include "teak.map"
#include "whiteash.map"

#declare Cols = 10;
#declare Rows = 2;
camera { orthographic location <0, 0, -100> direction z right x * Cols up y * Rows * 1.1 }
light_source { <-30, 40, -50> color rgb 1 }
light_source { <40, 10, -30> color rgb 0.3 shadowless }
background { color rgb 0.3 }

#macro Cell(I, Row) <I - (Cols - 1) / 2, 0.5 - Row, 0> #end
// Swatch(I, Pattern, Map): map Map on pattern Pattern in column I.
#macro Swatch(I, Pattern, Map)
	sphere { 0, 0.45 pigment { Pattern color_map { Map } }
		finish { specular 0.3 roughness 0.02 } translate Cell(I, 0) }
	box { <-0.3, -0.48, 0>, <0.3, 0.48, 0.1>
		pigment { gradient y color_map { Map } scale 0.96 translate -0.48 * y }
		finish { ambient 1 diffuse 0 } translate Cell(I, 1) }
#end
#declare Wood = pigment { wood turbulence 0.04 scale 0.12 rotate <70, 20, 0> }
#declare Agate = pigment { agate scale 0.5 }
#declare Granite = pigment { granite scale 0.8 }
Swatch(0, Wood, M_Ash)
Swatch(1, Wood, M_Benediti)
Swatch(2, Wood, M_Bubinga)
Swatch(3, Wood, M_Cedar)
Swatch(4, Wood, M_Orangewood)
Swatch(5, Wood, M_Teak)
Swatch(6, Wood, M_WhiteAsh)
Swatch(7, Agate, M_MarbTeal)
Swatch(8, Agate, M_PinkMarb)
Swatch(9, Granite, M_RedGranite)
