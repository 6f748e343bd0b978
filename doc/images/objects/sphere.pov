// sphere.pov: a sphere on the floor, and a small one written without the comma.
#version 3.7;
#include "stage.inc"

sphere { <0, 1, 0>, 1 texture { T_Red } }
sphere { <1.7, 0.4, -0.8> 0.4 texture { T_Gold } }
