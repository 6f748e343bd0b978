// csg-modifiers.pov: modifiers every object has. Exercises clipped_by (a
// sphere cut into a cup; a cylinder clipped by two planes), bounded_by
// (larger than the object: no visible change), clipped_by { bounded_by },
// no_shadow, no_image (casts a shadow but is not seen), no_reflection
// (seen but not in the mirror), and split_union off.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -10> right x*image_width/image_height look_at <0, 1, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
// A mirror at the back.
box { <-6, 0, 3>, <6, 4, 3.2> pigment { color rgb 0.1 } finish { reflection 0.8 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }

sphere { 0, 1 clipped_by { plane { y, 0.3 } } rotate x*200 translate <-3.5, 1.2, 0>
  pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
cylinder { <0, 0, 0>, <0, 2.5, 0>, 0.6
  clipped_by { plane { <1, 1, 0>, 1.2 } plane { <-1, 0.2, -1>, 0.5 } }
  translate <-1.5, 0.01, 1> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
sphere { 0, 0.8 bounded_by { box { -1, 1 } } translate <0.3, 0.8, -0.5>
  pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
box { -0.7, 0.7 bounded_by { sphere { 0, 0.85 } } clipped_by { bounded_by }
  rotate <20, 30, 0> translate <2.2, 0.9, 0.5> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
sphere { <4, 2.5, -1>, 0.5 no_shadow pigment { color rgb <0.8, 0.4, 0.8> } }
sphere { <1.5, 2.8, -2>, 0.5 no_image pigment { color rgb <1, 1, 1> } }
sphere { <-2.5, 2.8, 0>, 0.4 no_reflection pigment { color rgb <0.2, 0.8, 0.8> } }
union {
  sphere { <0, 0.3, 0>, 0.3 }
  sphere { <0.5, 0.3, 0>, 0.3 }
  split_union off
  translate <-0.5, 0, -2.5> pigment { color rgb <1, 0.6, 0.3> } finish { Shiny }
}
