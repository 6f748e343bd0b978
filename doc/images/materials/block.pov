// block.pov: the block patterns checker, hexagon and brick on tiles, with
// their default colours on the left and their own lists elsewhere.
#version 3.7;
#include "stage.inc"

Tile(0, 3, texture { pigment { checker scale 0.25 } })
Tile(1, 3, texture { pigment { hexagon color rgb 0.9 color rgb <0.3, 0.5, 0.8> color rgb <0.9, 0.7, 0.2>
                               scale 0.12 rotate x*-90 } })
Tile(2, 3, texture { pigment { brick color rgb 0.85 color rgb <0.6, 0.2, 0.1> scale 0.05 } })
