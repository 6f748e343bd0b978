// warps.pov: one checker under four warps: repeat with flip,
// black_hole, turbulence and cylindrical.
#version 3.7;
#include "stage.inc"

#declare C = pigment { checker color rgb 0.9 color rgb <0.8, 0.2, 0.1> scale 0.1 };
Tile(0, 4, texture { pigment { gradient <1, 1, 0> color_map { [0 rgb 0.9] [1 rgb <0.8, 0.2, 0.1>] }
                               scale 0.5 warp { repeat x*0.5 flip x } } })
Tile(1, 4, texture { pigment { C warp { black_hole <0, 0.5, 0>, 0.45 strength 1.5 } } })
Tile(2, 4, texture { pigment { C warp { turbulence 0.3 } } })
Tile(3, 4, texture { pigment { checker color rgb 0.9 color rgb <0.8, 0.2, 0.1> scale <0.125, 0.25, 1>
                               warp { cylindrical } rotate x*90 translate y*0.5 } })
