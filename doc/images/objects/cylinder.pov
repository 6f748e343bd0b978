// cylinder.pov: a closed cylinder, and a slanted open one.
#version 3.7;
#include "stage.inc"

cylinder { <-1.3, 0, 0.3>, <-1.3, 1.8, 0.3>, 0.6 texture { T_Red } }
cylinder { <0.5, 0.5, -1>, <1.8, 1.5, 0.8>, 0.5 open texture { T_Green } }
