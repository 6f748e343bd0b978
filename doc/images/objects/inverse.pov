// inverse.pov: a box intersected with the outside of a sphere (left), and
// a sphere with another's inside flipped, which leaves only the bite
// (right; the same as a difference).
#version 3.7;
#include "stage.inc"

intersection {
  box { -0.7, 0.7 }
  sphere { 0, 0.9 inverse }
  texture { T_Cyan }
  rotate <30, 30, 0> translate <-1.3, 0.9, 0>
}
intersection {
  sphere { 0, 0.8 }
  sphere { <0.5, 0.4, -0.5>, 0.6 inverse }
  texture { T_Red }
  translate <1.3, 0.8, 0>
}
