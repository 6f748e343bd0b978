// shapes.pov: boxed, cylindrical, spherical and planar, each fading from
// white at its centre (value 1) to dark blue (value 0).
#version 3.7;
#include "stage.inc"

#declare Map = color_map { [0 rgb <0.1, 0.15, 0.4>] [1 rgb 1] };
Tile(0, 4, texture { pigment { boxed color_map { Map } scale 0.45 translate y*0.5 } })
Tile(1, 4, texture { pigment { cylindrical color_map { Map } scale 0.45 translate y*0.5 } })
Tile(2, 4, texture { pigment { spherical color_map { Map } scale 0.45 translate y*0.5 } })
Tile(3, 4, texture { pigment { planar color_map { Map } scale 0.45 translate y*0.5 } })
