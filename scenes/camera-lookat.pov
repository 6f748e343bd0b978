// camera-lookat.pov: camera placement. Exercises location and look_at
// from above and off-axis, sky tilting the view, angle, an explicit
// direction and up, and translate/rotate applied to the whole camera.
// The scene is an asymmetric L of coloured boxes with marker spheres on
// the axes, so any mirroring, roll or wrong field of view shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  perspective
  location <0, 0, -1>
  direction <0, 0, 1.2>
  up y
  right x*image_width/image_height
  sky <0.25, 1, 0>
  look_at <0, 0, 0>
  translate <0, 0, -4.5>
  rotate <30, -25, 0>
  translate <1.0, 0.8, 0>
}

light_source { <3, 10, -6> color rgb 1 }
light_source { <-8, 4, -2> color rgb 0.3 }

background { color rgb <0.6, 0.7, 0.9> }

plane { y, 0 pigment { color rgb <0.45, 0.45, 0.4> } }

box { <0, 0, 0>, <3, 0.4, 0.6> pigment { color rgb <0.9, 0.2, 0.2> } }   // +x arm
box { <0, 0, 0.6>, <0.6, 0.4, 2.5> pigment { color rgb <0.2, 0.4, 0.9> } } // +z arm
box { <0, 0.4, 0>, <0.6, 1.8, 0.6> pigment { color rgb <0.2, 0.8, 0.3> } } // +y post
sphere { <3.4, 0.3, 0.3>, 0.3 pigment { color rgb <1, 0.8, 0.8> } }
sphere { <0.3, 0.3, 2.9>, 0.3 pigment { color rgb <0.8, 0.8, 1> } }
sphere { <0.3, 2.1, 0.3>, 0.3 pigment { color rgb <0.8, 1, 0.8> } }
sphere { <-1.5, 0.5, -1>, 0.5 pigment { color rgb <0.9, 0.9, 0.2> } }
