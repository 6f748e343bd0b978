// csg-loose-box.pov: POV-Ray's box of an intersection leaves its inverse
// parts out, and a union's box includes its inverse parts' boxes, so an
// intersection with a union holding an inverse part gets a box smaller
// than its solid, and POV-Ray skips the rays that miss that box. Left: a
// cube minus a ball, written as intersection { box union { inverse ball,
// small sphere } }: its box is the ball's and the cube's overlap, so only
// a corner of the cube is drawn. Middle: the same as a part of a union
// (parts are skipped by their boxes too). Right: the same solid
// subtracted from a slab, where POV-Ray does not skip by box, so the
// square hole (with the ball's slice in it) is whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -9> right x*image_width/image_height look_at <0, 0, 0> angle 50 }
light_source { <4, 10, -6> color rgb 1 }
light_source { <-6, 5, -6> color rgb 0.4 }
background { color rgb <0.1, 0.11, 0.14> }
plane { y, -1.5 pigment { checker color rgb 0.7 color rgb 0.4 } }

#declare Loose = union { sphere { 0, 0.6 inverse } sphere { <1.5, 0, 0>, 0.4 } }
#declare Cut = intersection { box { -1, 1 } object { Loose } }

object { Cut pigment { color rgb <0.9, 0.6, 0.3> } translate <-2.8, 0, 0> }
union {
  object { Cut }
  sphere { <0, 1.6, 0>, 0.4 }
  pigment { color rgb <0.4, 0.8, 0.5> }
}
difference {
  box { <-1.5, -0.5, -1.5>, <1.5, 0.5, 1.5> }
  object { Cut }
  pigment { color rgb <0.5, 0.6, 0.95> }
  rotate 30*y
  translate <2.9, 0, 0.5>
}
