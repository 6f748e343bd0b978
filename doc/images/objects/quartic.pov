// quartic.pov: the "tooth" x^4 + y^4 + z^4 - x^2 - y^2 - z^2 = 0.
#version 3.7;
#include "stage.inc"

quartic {
  <1,                                       // x^4
   0, 0, 0,                                 // x^3y x^3z x^3
   0, 0, 0, 0, 0, -1,                       // x^2y^2 ... x^2
   0, 0, 0, 0, 0, 0, 0, 0, 0, 0,            // xy^3 ... x
   1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0, -1, 0, 0> // y^4 ... y^2 ... z^4 z^3 z^2 z 1
  sturm
  rotate <-20, 30, 0> translate <0, 1.3, 0> texture { T_Gold }
}
