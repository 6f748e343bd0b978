// scale.pov: the marker as made (left), mirrored by scale <-1, 1, 1>
// (middle), and scaled non-uniformly with a 0 that becomes 1 (right).
#version 3.7;
#include "stage.inc"

#declare Marker = union {
  box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> }
  sphere { <0.4, 0.8, -0.4>, 0.2 texture { T_Red } }
  texture { T_Blue }
}
object { Marker translate <-1.8, 0, 0> }
object { Marker scale <-1, 1, 1> }
object { Marker scale <0.6, 0, 1.6> translate <1.8, 0, 0> }   // warning: scale by 0 changed to 1
