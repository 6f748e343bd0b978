// plane.pov: the floor (from stage.inc), a back wall and a side wall
// whose normal points away from the origin's side.
#version 3.7;
#include "stage.inc"

plane { z, 2 texture { T_Blue } }
plane { -x, 2 texture { T_Gold } }
sphere { <0, 0.7, 0>, 0.7 texture { T_Red } }
