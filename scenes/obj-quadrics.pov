// obj-quadrics.pov: the quadric family. Exercises cylinder (closed, open,
// slanted), cone (closed, open, to a point), disc (plain and with a hole
// radius), and quadric (an ellipsoid, and a hyperboloid of one sheet
// clipped by a box), with phong highlights and shadows on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }

cylinder { <-4, 0, 1>, <-4, 2, 1>, 0.6 pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
cylinder { <-2.4, 0.1, 0>, <-1.6, 1.8, 1>, 0.5 open pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
cone { <0, 0, 1.5>, 0.9, <0, 2.2, 1.5>, 0 pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
cone { <1.8, 0.2, 0>, 0.2, <2.4, 1.6, -0.3>, 0.7 open pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
disc { <3.8, 1.2, 1>, <-1, 0.5, -1>, 1.0, 0.4 pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
disc { <-3.2, 0.01, -2>, y, 0.8 pigment { color rgb <0.2, 0.8, 0.8> } }
quadric { <1, 4, 1>, <0, 0, 0>, <0, 0, 0>, -0.36
  translate <-1, 0.4, -2.2> pigment { color rgb <1, 0.6, 0.3> } finish { Shiny } }
quadric { <1, -1, 1>, <0, 0, 0>, <0, 0, 0>, -0.15
  clipped_by { box { <-1, -0.8, -1>, <1, 0.8, 1> } }
  translate <1.4, 0.8, -2> pigment { color rgb <0.6, 0.9, 0.5> } finish { Shiny } }
