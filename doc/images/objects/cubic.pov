// cubic.pov: the monkey saddle y = x^3 - 3xz^2, clipped by a sphere.
#version 3.7;
#include "stage.inc"

cubic {
  <1,                            // x^3
   0, 0, 0,                      // x^2y x^2z x^2
   0, 0, 0, -3, 0, 0,            // xy^2 xyz xy xz^2 xz x
   0, 0, 0, 0, 0, -1, 0, 0, 0, 0> // y^3 y^2z y^2 yz^2 yz y z^3 z^2 z 1
  clipped_by { sphere { 0, 1.2 } }
  rotate y*20 translate <0, 1.1, 0> texture { T_Violet }
}
