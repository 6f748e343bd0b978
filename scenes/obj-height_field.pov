// obj-height_field.pov: height fields from functions: a landscape, one cut
// by water_level, one turned on its side, and one in CSG (a sphere carved out).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> right x*image_width/image_height look_at <0, 1, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
height_field { function 40, 30 { 0.5 + 0.25*sin(9*x)*cos(7*y) + 0.2*sin(20*x*y) }
  scale <3, 1.2, 2.4> translate <-3.6, 0, 0.6> pigment { color rgb <0.3, 0.7, 0.3> } finish { Shiny } }
height_field { function 24, 24 { 1 - 2*((x-0.5)*(x-0.5) + (y-0.5)*(y-0.5)) - 0.1*sin(25*x) }
  water_level 0.6 scale <2, 1.6, 2> translate <0.2, -0.2, 0.8> pigment { color rgb <0.9, 0.6, 0.2> } finish { Shiny } }
height_field { function 12, 12 { 0.3 + 0.2*cos(12*x)*sin(9*y) }
  rotate z*90 scale <1, 1.6, 1.6> translate <3.3, 0.2, 0.4> pigment { color rgb <0.3, 0.4, 0.9> } finish { Shiny } }
difference {
  height_field { function 30, 30 { 0.6 + 0.3*sin(15*x*x + 8*y) } translate <-0.5, 0, -0.5> scale <2, 1.5, 2> }
  sphere { <0.2, 1.4, -0.3>, 0.7 }
  translate <-0.3, 0, -2> pigment { color rgb <0.9, 0.3, 0.3> } finish { Shiny } }
