// transform.pov: translate, rotate and scale on a marker (a block with
// a knob on one corner): as made, rotated, and scaled.
#version 3.7;
#include "stage.inc"

#declare Marker = union {
  box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> }
  sphere { <0.4, 0.8, -0.4>, 0.2 texture { T_Red } }
  texture { T_Blue }
}
object { Marker translate <-1.8, 0, 0> }
object { Marker rotate <-30, 45, 0> translate <0, 0.5, 0> }
object { Marker scale <1.5, 0.5, 1> translate <1.8, 0, 0> }
