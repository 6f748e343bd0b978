// quadric.pov: an ellipsoid x^2 + 4y^2 + z^2 = 0.64, and a hyperboloid
// of one sheet x^2 - y^2 + z^2 = 0.15 clipped by a box.
#version 3.7;
#include "stage.inc"

quadric { <1, 4, 1>, <0, 0, 0>, <0, 0, 0>, -0.64 translate <-1.4, 0.4, 0> texture { T_Gold } }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15
  clipped_by { box { <-1, -0.9, -1>, <1, 0.9, 1> } }
  translate <1.3, 0.9, 0.3> texture { T_Green } }
