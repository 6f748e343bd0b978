// texture_map.pov: gradient y blends a shiny blue texture into a matt,
// bumpy brown one; a checker picks between two textures; a pigment_map
// blends two patterned pigments.
#version 3.7;
#include "stage.inc"

#declare Shiny = texture { pigment { rgb <0.2, 0.4, 0.9> } finish { phong 0.9 reflection 0.2 } };
#declare Rough = texture { pigment { rgb <0.5, 0.3, 0.15> } normal { bumps 0.8 scale 0.05 } };
Ball(0, 3, texture { gradient y texture_map { [0.4 Rough] [0.7 Shiny] } scale 1.1 })
Ball(1, 3, texture { checker texture { Shiny } texture { Rough } scale 0.3 })
Ball(2, 3, texture { pigment { gradient y
  pigment_map { [0.3 checker color rgb 1 color rgb 0.2 scale 0.15] [0.7 bozo color_map { [0 rgb <0.9, 0.5, 0.1>] [1 rgb <0.2, 0.5, 0.1>] } scale 0.1] }
  scale 1.1 } })
