// normals.pov: bumps, dents and wrinkles on grey balls.
#version 3.7;
#include "stage.inc"

#declare P = pigment { rgb <0.75, 0.75, 0.8> };
#declare F = finish { phong 0.6 phong_size 30 };
Ball(0, 3, texture { pigment { P } normal { bumps 0.6 scale 0.1 } finish { F } })
Ball(1, 3, texture { pigment { P } normal { dents 1.5 scale 0.2 } finish { F } })
Ball(2, 3, texture { pigment { P } normal { wrinkles 0.8 scale 0.3 } finish { F } })
