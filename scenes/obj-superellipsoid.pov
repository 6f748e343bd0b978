// obj-superellipsoid.pov: superellipsoid { <e, n> } across its range:
// rounded boxes (small e and n), a sphere (1, 1), a pinched octahedron
// (2, 2), cylinders and pillows (mixed), and a thin star (e = n = 3),
// rotated so that edges catch the light.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -11> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }
#declare Shapes = array[8] { <0.1, 0.1>, <0.25, 1>, <1, 1>, <2, 2>, <1, 0.2>, <0.2, 2.5>, <3, 3>, <0.5, 0.5> }
#for (I, 0, 7)
  superellipsoid { Shapes[I]
    scale 0.7 rotate <25, 30 + 20 * I, 0>
    translate <-3.6 + mod(I, 4) * 2.4, 1, select(I - 3.5, 1.5, -1)>
    pigment { color rgb <0.3 + 0.1 * I, 0.9 - 0.1 * I, 0.5> } finish { Shiny } }
#end
