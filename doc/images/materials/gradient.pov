// gradient.pov: gradient, onion, radial and spiral1 on tiles.
#version 3.7;
#include "stage.inc"

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.6>] [0.5 rgb <0.9, 0.9, 0.8>] [1 rgb <0.1, 0.2, 0.6>] };
Tile(0, 4, texture { pigment { gradient x color_map { Map } scale 0.5 } })
Tile(1, 4, texture { pigment { onion color_map { Map } scale 0.25 translate y*0.5 } })
Tile(2, 4, texture { pigment { radial frequency 6 color_map { Map } rotate x*-90 translate y*0.5 } })
Tile(3, 4, texture { pigment { spiral1 3 color_map { Map } scale 0.3 translate y*0.5 } })
