// bounded_by.pov: a sphere in a box bound (no visible change), and a box
// clipped by its own bounding sphere with clipped_by { bounded_by }.
#version 3.7;
#include "stage.inc"

sphere { 0, 0.8 bounded_by { box { -0.81, 0.81 } }
  translate <-1.3, 0.8, 0> texture { T_Blue } }
box { -0.7, 0.7
  bounded_by { sphere { 0, 1.1 } }
  clipped_by { bounded_by }
  rotate <20, 30, 0> translate <1.3, 0.9, 0> texture { T_Gold } }
