// isosurface.pov: a rounded box from a function, a torus in a sphere
// container, and a noisy blob cut open by its box container.
#version 3.7;
#declare Stage_From = <0, 3, -6.5>;
#declare Stage_At = <0, 0.8, 0>;
#include "stage.inc"

#declare RoundBox = function { pow(pow(x, 8) + pow(y, 8) + pow(z, 8), 1/8) }
#declare Tor = function { sqrt(pow(sqrt(x*x + z*z) - 0.6, 2) + y*y) - 0.25 }
isosurface { function { RoundBox(x, y, z) } threshold 0.8 max_gradient 1.8
  translate <-2.2, 0.8, 0.3> texture { T_Red } }
isosurface { function { Tor(x, y, z) } contained_by { sphere { 0, 0.9 } }
  rotate x*-50 translate <0, 0.9, 0> texture { T_Green } }
isosurface { function { sqrt(x*x + y*y + z*z) - 0.2*sin(6*x)*sin(6*y)*sin(6*z) }
  threshold 0.8 contained_by { box { <-1, -1, -1>, <1, 0.4, 1> } } max_gradient 2.4 open
  translate <2.2, 0.85, 0.3> texture { T_Blue } }
