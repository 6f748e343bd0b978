// tiling.pov: four of the 27 tilings, each with a map that gives every
// tile type its colour and darkens the bevel towards the grout.
#version 3.7;
#include "stage.inc"

// A map for N tile types: type t's face (t/N) in colour C[t], fading to
// dark grout at its edges ((t+1)/N).
#macro TileMap(N, C)
  color_map {
    #local T = 0;
    #while (T < N)
      [T/N color C[T]]
      [(T + 0.6)/N color C[T]]
      [(T + 1)/N - 0.0001 color rgb 0.05]
      #local T = T + 1;
    #end
  }
#end
#declare Cols = array[6] { rgb <0.85, 0.75, 0.55>, rgb <0.3, 0.45, 0.7>, rgb <0.75, 0.3, 0.2>,
                           rgb <0.4, 0.6, 0.35>, rgb <0.9, 0.9, 0.85>, rgb <0.6, 0.45, 0.7> }
Tile(0, 4, texture { pigment { tiling 7 TileMap(2, Cols) scale 0.18 rotate x*-90 } })
Tile(1, 4, texture { pigment { tiling 16 TileMap(3, Cols) scale 0.12 rotate x*-90 } })
Tile(2, 4, texture { pigment { tiling 21 TileMap(6, Cols) scale 0.15 rotate x*-90 } })
Tile(3, 4, texture { pigment { tiling 24 TileMap(5, Cols) scale 0.08 rotate x*-90 } })
