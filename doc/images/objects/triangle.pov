// triangle.pov: two triangles standing on the floor.
#version 3.7;
#include "stage.inc"

triangle { <-2.2, 0, 0.5>, <-0.3, 0, 1>, <-1.3, 1.9, 0.2> texture { T_Red } }
triangle { <0.3, 0, -0.3>, <2.2, 0, 0.2>, <1.4, 1.7, 0.8> texture { T_Gold } }
