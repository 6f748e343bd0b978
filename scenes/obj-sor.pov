// obj-sor.pov: surfaces of revolution: the manual's open vase, a closed
// bottle with sturm, one in CSG (cut by a box) and one turned on its side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> right x*image_width/image_height look_at <0, 1, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
sor { 7, <0.000000, 0.000000> <0.118143, 0.000000> <0.620253, 0.540084> <0.210970, 0.827004>
  <0.194093, 0.962025> <0.286920, 1.000000> <0.468354, 1.033755>
  open scale 2.4 translate <-3, 0, 1.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
sor { 8, <0, -0.5>, <0.8, 0>, <0.9, 0.8>, <0.85, 1.5>, <0.35, 2>, <0.3, 2.6>, <0.38, 2.8>, <0.3, 3.2>
  sturm translate <0, 0, 1.5> pigment { color rgb <0.2, 0.6, 0.3> } finish { Shiny } }
difference {
  sor { 5, <0, -1>, <1, 0>, <0.5, 1>, <1, 2>, <0, 3> }
  box { <0, -1, -2>, <2, 3, 0> }
  rotate y*-40 translate <3, 0, 1.2> pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
sor { 6, <0.5, -1>, <0.3, 0>, <0.6, 0.6>, <0.2, 1.2>, <0.6, 1.8>, <0.3, 2.6>
  rotate z*90 translate <-0.5, 0.6, -1.8> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
