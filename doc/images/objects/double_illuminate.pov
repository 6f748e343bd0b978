// double_illuminate.pov: two discs lit only from behind; the right one
// has double_illuminate.
#version 3.7;
#declare Stage_Lights = false;
#include "stage.inc"

light_source { <0, 4, 6> color rgb 1 }
disc { <-1.2, 1, 0>, -z, 0.9 texture { T_White } }
disc { <1.2, 1, 0>, -z, 0.9 double_illuminate texture { T_White } }
