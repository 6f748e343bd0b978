// smooth_triangle.pov: the same triangle flat (left) and with vertex
// normals that lean outward (right).
#version 3.7;
#include "stage.inc"

#declare A = <-1, 0, 0>;
#declare B = <1, 0, 0>;
#declare C = <0, 1.7, 0>;
triangle { A, B, C translate <-1.2, 0.1, 0> texture { T_Cyan } }
smooth_triangle { A, <-1, -0.3, -1>, B, <1, -0.3, -1>, C, <0, 1, -1>
  translate <1.2, 0.1, 0> texture { T_Cyan } }
