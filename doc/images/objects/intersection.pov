// intersection.pov: a lens (two spheres) and a rounded cube (a box and a
// sphere).
#version 3.7;
#include "stage.inc"

intersection {
  sphere { <0, 0, -0.6>, 1 }
  sphere { <0, 0, 0.6>, 1 }
  texture { T_Blue }
  rotate <0, 60, 0> translate <-1.3, 0.8, 0>
}
intersection {
  box { -0.7, 0.7 }
  sphere { 0, 0.9 }
  texture { T_Gold }
  rotate y*30 translate <1.3, 0.7, 0>
}
