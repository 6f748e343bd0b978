// image_map.pov: the 4 x 2 test picture rgb.png on a tile (map_type 0),
// the same interpolated (interpolate 2), and wrapped round a ball (map_type 1).
#version 3.7;
#include "stage.inc"

Tile(0, 3, texture { pigment { image_map { png "../../../tests/data/images/rgb.png" } translate x*-0.5 } })
Tile(1, 3, texture { pigment { image_map { png "../../../tests/data/images/rgb.png" interpolate 2 } translate x*-0.5 } })
Ball(2, 3, texture { pigment { image_map { png "../../../tests/data/images/rgb.png" map_type 1 } } })
