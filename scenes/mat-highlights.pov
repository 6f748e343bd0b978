// mat-highlights.pov: highlights. phong and specular with albedo, metallic
// with an amount (its tint turns to the light's colour toward grazing
// light), highlights on a filtering surface (not scaled by the filter).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -10> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 2, -3> color rgb <0.5, 0.6, 0.4> }
background { color rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { color rgb 0.5 } }
#declare P = pigment { color rgb <0.9, 0.5, 0.1> }
sphere { <-3.3, 0.7, 1.5>, 0.7 pigment { P } finish { phong albedo 0.3 phong_size 20 } }
sphere { <-1.1, 0.7, 1.5>, 0.7 pigment { P } finish { specular albedo 0.4 roughness 0.03 } }
sphere { < 1.1, 0.7, 1.5>, 0.7 pigment { P } finish { phong 0.9 phong_size 8 metallic 0.5 } }
sphere { < 3.3, 0.7, 1.5>, 0.7 pigment { P } finish { specular 0.9 roughness 0.2 metallic } }
sphere { <-3.3, 0.7, -1>, 0.7 pigment { rgbf <0.9, 0.5, 0.1, 0.7> } finish { phong 1 } }
sphere { <-1.1, 0.7, -1>, 0.7 pigment { P } finish { phong 0.5 specular 0.5 roughness 0.01 } }
sphere { < 1.1, 0.7, -1>, 0.7 pigment { P } finish { specular 1 roughness 0.5 metallic 1 diffuse 0.2 } }
sphere { < 3.3, 0.7, -1>, 0.7 pigment { P } finish { phong albedo 0.9 phong_size 200 } }
