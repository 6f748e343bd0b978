// cells.pov: crackle, cells and leopard.
#version 3.7;
#include "stage.inc"

Ball(0, 3, texture { pigment { crackle color_map { [0 rgb 0.05] [0.08 rgb <0.9, 0.8, 0.5>] [1 rgb <0.6, 0.4, 0.2>] } scale 0.25 } })
Ball(1, 3, texture { pigment { cells color_map { [0 rgb <0.1, 0.3, 0.8>] [1 rgb <0.9, 0.9, 0.3>] } scale 0.2 } })
Ball(2, 3, texture { pigment { leopard color_map { [0 rgb <0.9, 0.7, 0.3>] [0.4 rgb <0.9, 0.7, 0.3>] [0.6 rgb 0.1] [1 rgb 0.1] } scale 0.06 } })
