// ripples.pov: ripples, waves, facets and quilted normals.
#version 3.7;
#include "stage.inc"

#declare P = pigment { rgb <0.75, 0.75, 0.8> };
#declare F = finish { phong 0.6 phong_size 30 };
Ball(0, 4, texture { pigment { P } normal { ripples 1.2 scale 0.2 } finish { F } })
Ball(1, 4, texture { pigment { P } normal { waves 1.2 scale 0.2 } finish { F } })
Ball(2, 4, texture { pigment { P } normal { facets size 0.25 } finish { F } })
Ball(3, 4, texture { pigment { P } normal { quilted 0.8 control0 0 control1 1 scale 0.2 } finish { F } })
