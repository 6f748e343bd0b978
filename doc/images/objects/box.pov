// box.pov: two boxes; the second gives its corners in another order.
#version 3.7;
#include "stage.inc"

box { <-2, 0, -0.5>, <-0.6, 1.4, 0.9> texture { T_Blue } }
box { <1.9, 0.8, 0.6>, <0.3, 0, -0.8> rotate y*-20 texture { T_Gold } }
