// csg-ops.pov: the four CSG operations and inverse. Exercises union (with
// a texture that children without their own inherit), merge (no inner
// surfaces: seen through a transmit-free cut), intersection (a lens),
// difference (a box with spherical bites, and one with 40 holes, whose
// subtracted children go into the CSG's own hierarchy), an inverse child
// in an intersection, and transforms applied to whole CSG objects.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }

union {
  sphere { <-0.4, 0, 0>, 0.6 }
  sphere { <0.4, 0, 0>, 0.6 pigment { color rgb <1, 1, 0.3> } }
  cylinder { <0, -0.8, 0>, <0, 0.8, 0>, 0.2 }
  pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny }
  rotate z*20 translate <-3.5, 1, 1.5>
}
// A merge cut open by a difference shows no inner surfaces.
difference {
  merge {
    sphere { <-0.4, 0, 0>, 0.6 }
    sphere { <0.4, 0, 0>, 0.6 }
  }
  box { <-2, -2, -2>, <2, 2, 0> }
  pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny }
  rotate y*-35 translate <-1, 0.6, 2>
}
intersection {
  sphere { <0, 0, -0.5>, 1 }
  sphere { <0, 0, 0.5>, 1 }
  pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny }
  rotate <20, 40, 0> translate <1.5, 1, 2>
}
difference {
  box { -0.8, 0.8 }
  sphere { <0.8, 0.8, -0.8>, 0.6 }
  sphere { <-0.8, 0.8, -0.8>, 0.4 pigment { color rgb <1, 1, 1> } }
  cylinder { <0, 0, -1>, <0, 0, 1>, 0.3 }
  pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny }
  rotate y*25 translate <3.6, 0.8, 1.5>
}
#declare R = seed(7);
difference {
  box { <-1.2, 0, -0.3>, <1.2, 1.4, 0.3> }
  #for (I, 1, 40)
    sphere { <-1.2 + 2.4 * rand(R), 1.4 * rand(R), -0.3>, 0.08 + 0.1 * rand(R) }
  #end
  pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny }
  translate <-1.6, 0, -1.6>
}
intersection {
  box { -0.7, 0.7 }
  sphere { 0, 0.9 inverse }
  pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny }
  rotate <30, 30, 0> translate <1.8, 0.9, -1.5>
}
