// transform_block.pov: a declared transform used as it is (left), undone
// by transform { Lift inverse } (middle), and a block that holds a scale
// and the identifier (right).
#version 3.7;
#include "stage.inc"

#declare Lift = transform { scale <1, 2, 1> rotate z*30 translate <0, 0.9, 0> }
sphere { 0, 0.4 transform Lift translate <-1.8, 0, 0> texture { T_Green } }
sphere { <0, 0.4, 0>, 0.4 transform Lift transform { Lift inverse } texture { T_Green } }
sphere { 0, 0.4 transform { scale <2, 0.5, 1> Lift translate <1.8, 0, 0> } texture { T_Green } }
