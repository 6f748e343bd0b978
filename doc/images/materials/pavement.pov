// pavement.pov: four pavements: pentiamonds, an S tetromino with
// rounded turns, hexominoes with cut corners, and tri-hexes with
// rounded corners.
#version 3.7;
#include "stage.inc"

#declare M = color_map { [0 rgb <0.3, 0.45, 0.7>] [0.55 rgb <0.85, 0.75, 0.55>] [0.85 rgb <0.6, 0.25, 0.15>] [1 rgb 0.05] }
Tile(0, 4, texture { pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 3 color_map { M } scale 0.22 rotate x*-90 } })
Tile(1, 4, texture { pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 color_map { M } scale 0.17 rotate x*-90 } })
Tile(2, 4, texture { pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 20 exterior 1 interior 1 color_map { M } scale 0.13 rotate x*-90 } })
Tile(3, 4, texture { pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 2 form 2 interior 2 color_map { M } scale 0.13 rotate x*-90 } })
