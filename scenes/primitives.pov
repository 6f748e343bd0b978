// primitives.pov: every primitive lucent has so far. Exercises sphere,
// box (axis-aligned, then rotated), plane (ground and a back wall given
// as normal and distance, with a negative distance), object { Ident } of
// #declare'd objects carrying their own textures, and overriding a
// declared object's pigment at the point of use.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare Ball = sphere { 0, 0.6 pigment { color rgb <0.2, 0.5, 0.9> } }
#declare Crate = box { <-0.5, 0, -0.5>, <0.5, 1, 0.5>
  pigment { color rgb <0.9, 0.6, 0.2> } }

camera {
  location <0, 3, -7>
  right x*image_width/image_height
  look_at <0, 0.7, 0>
  angle 50
}

light_source { <4, 9, -7> color rgb 1 }

background { color rgb <0.1, 0.1, 0.15> }

plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } }
plane { -z, -4 pigment { color rgb <0.5, 0.6, 0.5> } }

object { Ball translate <-2, 0.6, 0> }
object { Ball translate <2, 0.6, 0.5> pigment { color rgb <0.9, 0.2, 0.3> } }
object { Crate translate <-0.6, 0, -0.4> }
object { Crate rotate y*35 translate <0.9, 0, 2.6> }
box { <-0.3, 0, -0.3>, <0.3, 2.2, 0.3>
  rotate <0, 20, 0> translate <-3.2, 0, 2.5>
  pigment { color rgb <0.4, 0.8, 0.4> } }
sphere { <3.1, 1.6, 2.5>, 0.35 pigment { color rgb <1, 1, 0.6> } }
