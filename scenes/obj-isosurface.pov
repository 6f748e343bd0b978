// obj-isosurface.pov: isosurfaces: a sphere function in the default box,
// a torus in a sphere container, a box-cut noisy blob (open, so the cut
// shows the inside), one in CSG, one with max_trace, and one whose
// surface leaves its container (the container's walls show).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -10> right x*image_width/image_height look_at <0, 1, 0> angle 48 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
#declare Sph = function { sqrt(x*x + y*y + z*z) }
#declare Tor = function { sqrt(pow(sqrt(x*x + z*z) - 0.8, 2) + y*y) - 0.3 }
isosurface { function { Sph(x, y, z) } threshold 0.9
  translate <-3.5, 1, 2> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
isosurface { function { Tor(x, y, z) } contained_by { sphere { 0, 1.2 } } max_gradient 1.2
  rotate x*60 translate <-1, 1.2, 2> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
isosurface { function { Sph(x, y, z) - 0.25*sin(5*x)*sin(5*y)*sin(5*z) } threshold 0.8
  contained_by { box { <-1, -1, -1>, <1, 0.5, 1> } } max_gradient 2.5 open
  translate <1.5, 1, 2> pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
difference {
  isosurface { function { abs(x) + abs(y) + abs(z) } threshold 1 max_gradient 1.8 }
  sphere { <0.5, 0.5, -0.5>, 0.7 }
  translate <3.6, 1, 1.5> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
isosurface { function { y - 0.3*sin(3*x)*cos(3*z) } contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
  max_gradient 2 max_trace 2
  translate <-2, 0.5, -1.5> pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
isosurface { function { x*x + z*z - 0.5 } accuracy 0.0005 max_gradient 3 all_intersections
  translate <1.8, 1, -1.5> pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny } }
