// no_shadow.pov: two spheres above the floor; the right one casts no shadow.
#version 3.7;
#include "stage.inc"

sphere { <-1.2, 1.2, 0>, 0.6 texture { T_Red } }
sphere { <1.2, 1.2, 0>, 0.6 no_shadow texture { T_Red } }
