// wood.pov: wood, agate and spotted with their built-in colour maps
// (spotted's is the grey ramp).
#version 3.7;
#include "stage.inc"

Ball(0, 3, texture { pigment { wood turbulence 0.05 scale 0.08 rotate x*80 } })
Ball(1, 3, texture { pigment { agate scale 0.5 } })
Ball(2, 3, texture { pigment { spotted scale 0.15 } })
