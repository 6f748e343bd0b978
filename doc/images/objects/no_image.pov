// no_image.pov: a mirror behind two spheres; the right one has no_image:
// the camera does not see it, but the mirror and the shadows still do.
#version 3.7;
#include "stage.inc"

box { <-3, 0, 1.5>, <3, 2.5, 1.6> pigment { color rgb 0.1 } finish { reflection 0.8 } }
sphere { <-1.1, 0.9, -0.3>, 0.6 texture { T_Gold } }
sphere { <1.1, 0.9, -0.3>, 0.6 no_image texture { T_Gold } }
