// fractals.pov: mandel, julia and magnet on tiles (they lie in the x-y plane).
#version 3.7;
#include "stage.inc"

#declare Map = color_map { [0 rgb 0] [0.2 rgb <0.2, 0.4, 0.9>] [0.5 rgb <0.9, 0.9, 0.5>] [1 rgb 1] };
Tile(0, 3, texture { pigment { mandel 30 scale 0.35 translate <0.15, 0.5, 0> } })
Tile(1, 3, texture { pigment { julia <0.353, 0.288>, 30 color_map { Map } scale 0.35 translate y*0.5 } })
Tile(2, 3, texture { pigment { magnet 1 mandel 30 color_map { Map } scale 0.2 translate <-0.2, 0.5, 0> } })
