// height_field.pov: height fields from functions: rolling hills, an island
// cut by water_level, and the same hills with smooth normals.
#version 3.7;
#declare Stage_From = <0, 3.5, -6.5>;
#declare Stage_At = <0, 0.9, 0.3>;
#include "stage.inc"

#declare Hills = function { 0.5 + 0.25*sin(9*x)*cos(7*y) + 0.2*sin(20*x*y) }
height_field { function 30, 24 { Hills(x, y, 0) }
  scale <2.2, 1, 1.8> translate <-3.3, 0, 0.2> texture { T_Green } }
height_field { function 24, 24 { 1 - 2*((x-0.5)*(x-0.5) + (y-0.5)*(y-0.5)) - 0.1*sin(25*x) }
  water_level 0.6 scale <2, 1.6, 2> translate <-1, -0.5, 0.5> texture { T_Gold } }
height_field { function 30, 24 { Hills(x, y, 0) } smooth
  scale <2.2, 1, 1.8> translate <1.2, 0, 0.2> texture { T_Green } }
