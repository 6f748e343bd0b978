// waves.pov: gradient x with frequency 2 under ramp_wave, triangle_wave,
// sine_wave and scallop_wave, on tiles.
#version 3.7;
#include "stage.inc"

#declare Map = color_map { [0 rgb <0.1, 0.15, 0.4>] [1 rgb 1] };
Tile(0, 4, texture { pigment { gradient x color_map { Map } frequency 2 ramp_wave translate x*-0.5 } })
Tile(1, 4, texture { pigment { gradient x color_map { Map } frequency 2 triangle_wave translate x*-0.5 } })
Tile(2, 4, texture { pigment { gradient x color_map { Map } frequency 2 sine_wave translate x*-0.5 } })
Tile(3, 4, texture { pigment { gradient x color_map { Map } frequency 2 scallop_wave translate x*-0.5 } })
