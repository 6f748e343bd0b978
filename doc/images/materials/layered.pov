// layered.pov: a layered texture: red marble, with a layer of white
// spots that are transparent between them, then the same layers apart.
#version 3.7;
#include "stage.inc"

#declare Base = texture { pigment { marble turbulence 0.6 color_map { [0 rgb <0.7, 0.1, 0.1>] [1 rgb <0.3, 0, 0>] } scale 0.4 } finish { phong 0.5 } };
#declare Spots = texture { pigment { bozo color_map { [0.6 rgbt <1, 1, 1, 1>] [0.6 rgb 0.95] } scale 0.12 } };
Ball(0, 3, Base)
Ball(1, 3, texture { Spots })
sphere { <0, 0.5, 0>, 0.5 texture { Base } texture { Spots } Slot(2, 3) }
