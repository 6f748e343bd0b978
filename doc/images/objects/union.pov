// union.pov: two spheres and a rod; the union's texture goes to the
// children that have none.
#version 3.7;
#include "stage.inc"

union {
  sphere { <-0.6, 0, 0>, 0.6 }
  sphere { <0.6, 0, 0>, 0.6 texture { T_Gold } }
  cylinder { <0, -0.9, 0>, <0, 0.9, 0>, 0.2 }
  texture { T_Red }
  rotate z*20 translate <0, 1, 0>
}
