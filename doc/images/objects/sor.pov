// sor.pov: the manual's vase (open), a closed bottle, and one cut by a box.
#version 3.7;
#declare Stage_From = <0, 3.5, -6.5>;
#declare Stage_At = <0, 0.9, 0.3>;
#include "stage.inc"

sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084> <0.210970, 0.827004>
  <0.194093, 0.962025> <0.286920, 1.000000> <0.468354, 1.033755>
  open scale 2 translate <-2.2, 0, 0.5> texture { T_Red } }
sor { 8, <0, -0.5>, <0.7, 0>, <0.8, 0.7>, <0.75, 1.3>, <0.3, 1.7>, <0.25, 2.2>, <0.32, 2.35>, <0.25, 2.7>
  texture { T_Green } }
difference {
  sor { 5, <0, -1>, <0.8, 0>, <0.4, 0.8>, <0.8, 1.6>, <0, 2.4> }
  box { <0, -1, -2>, <2, 3, 0> }
  rotate y*-40 translate <2.2, 0, 0.3> texture { T_Blue } }
