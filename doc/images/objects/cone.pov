// cone.pov: a cone to a point, and an open truncated cone (a cup).
#version 3.7;
#include "stage.inc"

cone { <-1.3, 0, 0.3>, 0.8, <-1.3, 2, 0.3>, 0 texture { T_Blue } }
cone { <1.2, 0, 0>, 0.3, <1.2, 1.3, 0>, 0.8 open texture { T_Gold } }
