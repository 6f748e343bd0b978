// reflection.pov: a plain mirror (reflection 0.6), a fresnel reflection
// that grows towards the edge, and metallic reflection tinted by the pigment.
#version 3.7;
#declare Stage_Floor = false;
#include "stage.inc"

plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.25 } }
Ball(0, 3, texture { pigment { rgb 0.1 } finish { reflection 0.6 phong 0.8 } })
sphere { <0, 0.5, 0>, 0.5 Slot(1, 3)
  texture { pigment { rgb <0.05, 0.1, 0.3> } finish { reflection { 0, 1 fresnel } conserve_energy phong 0.8 } }
  interior { ior 1.5 } }
Ball(2, 3, texture { pigment { rgb <0.9, 0.6, 0.2> } finish { diffuse 0.1 reflection { 0.8 metallic } } })
