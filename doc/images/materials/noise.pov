// noise.pov: bozo and marble (with turbulence) with their built-in
// colour maps, and granite with a grey map of its own.
#version 3.7;
#include "stage.inc"

Ball(0, 3, texture { pigment { bozo scale 0.25 } })
Ball(1, 3, texture { pigment { granite color_map { [0 rgb 0.9] [0.5 rgb 0.5] [1 rgb 0.1] } scale 0.5 } })
Ball(2, 3, texture { pigment { marble turbulence 0.8 scale 0.3 } })
