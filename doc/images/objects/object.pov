// object.pov: one declared object placed three times, the last with its
// own pigment; and an object statement wrapped around an inline object.
#version 3.7;
#include "stage.inc"

#declare Post = cylinder { 0, <0, 1.4, 0>, 0.25 texture { T_Gold } }
object { Post translate <-2, 0, 0.5> }
object { Post rotate z*-30 translate <-0.8, 0, 0.5> }
object { Post scale <1, 0.6, 1> translate <0.4, 0, 0.5> pigment { color rgb <0.9, 0.25, 0.2> } }
object { box { -0.4, 0.4 } rotate y*45 translate <1.8, 0.4, 0> texture { T_Blue } }
