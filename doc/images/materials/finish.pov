// finish.pov: the same red under four finishes: the default (ambient 0.1,
// diffuse 0.6), a strong ambient, brilliance 4, and emission.
#version 3.7;
#include "stage.inc"

#declare Red = pigment { color rgb <0.9, 0.2, 0.15> };
Ball(0, 4, texture { pigment { Red } })
Ball(1, 4, texture { pigment { Red } finish { ambient 0.5 diffuse 0.4 } })
Ball(2, 4, texture { pigment { Red } finish { diffuse 0.9 brilliance 4 } })
Ball(3, 4, texture { pigment { Red } finish { emission 0.8 diffuse 0.2 } })
