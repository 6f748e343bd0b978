// highlights.pov: phong, specular, metallic and iridescence on the same gold.
#version 3.7;
#include "stage.inc"

#declare Gold = pigment { color rgb <0.85, 0.6, 0.15> };
Ball(0, 4, texture { pigment { Gold } finish { phong 0.9 phong_size 20 } })
Ball(1, 4, texture { pigment { Gold } finish { specular 0.8 roughness 0.005 } })
Ball(2, 4, texture { pigment { Gold } finish { diffuse 0.3 specular 0.9 roughness 0.02 metallic } })
Ball(3, 4, texture { pigment { rgb 0.5 } finish { diffuse 0.7 irid { 0.6 thickness 0.4 } phong 0.5 } })
