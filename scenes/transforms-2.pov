// transforms-2.pov: transformations beyond translate/rotate/scale.
// Exercises matrix (a shear), transform identifiers, transform blocks
// with inverse (undoing a declared transform), a negative scale
// (mirroring a cone), non-uniform scale of a torus and a box, and
// transforms applied to a CSG and to the clip object with it.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }
#declare Lift = transform { scale <1, 2, 1> rotate z*30 translate <0, 1, 0> }

box { <-0.5, 0, -0.5>, <0.5, 1.5, 0.5>
  matrix <1, 0, 0, 0.6, 1, 0, 0, 0, 1, 0, 0, 0>
  translate <-3.5, 0, 1> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
sphere { 0, 0.5 transform Lift translate <-1.8, 0, 1.5> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
sphere { <0, 1.2, 0>, 0.5 transform Lift transform { Lift inverse } translate <0, 0, 1.5>
  pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
cone { <0, 0, 0>, 0.6, <1.2, 1.4, 0>, 0.1 scale <-1, 1, 1> translate <2.4, 0, 1.5>
  pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
torus { 0.6, 0.2 scale <1.5, 3, 0.7> rotate x*-60 translate <-2.2, 1, -1.6>
  pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
difference {
  box { -0.6, 0.6 }
  sphere { 0, 0.75 }
  clipped_by { plane { y, 0.4 } }
  scale <1.5, 1, 0.8> rotate <0, 40, 15> translate <0.6, 0.6, -1.8>
  pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny }
}
box { -0.4, 0.4 scale <0.5, 2, 1> rotate <10, 20, 30> translate <3.2, 1, -1.2>
  pigment { color rgb <1, 0.6, 0.3> } finish { Shiny } }
