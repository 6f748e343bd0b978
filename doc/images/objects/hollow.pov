// hollow.pov: two clear boxes in a white fog, in front of a checkered
// wall (its normal faces the camera, so the camera is outside it).
// The left one is solid (the default): a ray inside it gets no fog,
// so the wall shows clearly through it. The right one is hollow: the fog
// fills it, and the wall behind it is as faint as elsewhere.
#version 3.7;
#declare Stage_Floor = false;
#include "stage.inc"

fog { distance 5 color rgb <0.85, 0.85, 0.9> }
plane { -z, -3 pigment { checker color rgb <0.9, 0.25, 0.2> color rgb 0.95 scale 0.5 } finish { ambient 0.6 } }
#declare Clear = texture { pigment { color rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
box { <-2.4, 0, -1.5>, <-0.2, 2.2, 2.5> texture { Clear } }
box { <0.2, 0, -1.5>, <2.4, 2.2, 2.5> hollow texture { Clear } }
