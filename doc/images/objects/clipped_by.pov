// clipped_by.pov: a sphere clipped to a bowl by a plane, and a cylinder
// clipped by two planes at once (it keeps what lies inside both).
#version 3.7;
#include "stage.inc"

sphere { 0, 1 clipped_by { plane { y, 0.3 } }
  rotate x*200 translate <-1.3, 1.2, 0> texture { T_Red } }
cylinder { <0, 0, 0>, <0, 2.2, 0>, 0.6
  clipped_by { plane { <1, 1, 0>, 1.3 } plane { <-1, 0.2, -1>, 0.5 } }
  translate <1.3, 0.01, 0.3> texture { T_Green } }
