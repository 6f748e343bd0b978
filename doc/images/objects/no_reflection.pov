// no_reflection.pov: a mirror behind two spheres; the right one has
// no_reflection: the camera sees it and its shadow, the mirror does not.
#version 3.7;
#include "stage.inc"

box { <-3, 0, 1.5>, <3, 2.5, 1.6> pigment { color rgb 0.1 } finish { reflection 0.8 } }
sphere { <-1.1, 0.9, -0.3>, 0.6 texture { T_Violet } }
sphere { <1.1, 0.9, -0.3>, 0.6 no_reflection texture { T_Violet } }
