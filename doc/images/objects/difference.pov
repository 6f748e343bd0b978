// difference.pov: a box with a spherical bite taken out of one corner and
// a hole drilled through it; each cut surface keeps its own texture.
#version 3.7;
#include "stage.inc"

difference {
  box { -0.8, 0.8 }
  sphere { <0.8, 0.8, -0.8>, 0.7 texture { T_White } }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.35 }
  cylinder { <-1, -0.2, 0>, <1, -0.2, 0>, 0.2 texture { T_Green } }
  texture { T_Gold }
  rotate y*25 translate <0, 0.8, 0>
}
