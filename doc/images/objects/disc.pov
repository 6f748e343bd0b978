// disc.pov: a ring (a disc with a hole) turned toward the camera, and a
// plain disc lying just above the floor.
#version 3.7;
#include "stage.inc"

disc { <-0.9, 1.2, 0.5>, <0.4, 0.2, -1>, 1, 0.45 texture { T_Violet } }
disc { <1.5, 0.01, -0.6>, y, 0.8 texture { T_Cyan } }
