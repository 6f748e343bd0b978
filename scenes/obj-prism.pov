// obj-prism.pov: prisms. Exercises every spline (linear with an automatic
// close and a hole from a second sub-prism, quadratic, cubic with three
// nested sub-prisms, bezier), conic_sweep (a pyramid and a capless
// ziggurat with first height 0.25), open, sturm, a prism in CSG (a
// difference with a box) and POV-Ray's logo from logo.inc.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "logo.inc"

camera { location <0, 7, -11> right x*image_width/image_height look_at <0, 0.6, 0.6> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.5 phong_size 30 }

// A frame: the inner rim cuts a hole; it is the last sub-prism and is
// closed for us.
prism { linear_spline 0, 0.6, 9,
  <0,0>, <2,0>, <2,1.6>, <0,1.6>, <0,0>,
  <0.4,0.4>, <1.6,0.4>, <1.6,1.2>, <0.4,1.2>
  translate <-4.6, 0, 1.8> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
// The manual's quadratic example, scaled down.
prism { quadratic_spline 0, 1, 12,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>,
  <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale <0.25, 1, 0.2> translate <-1.6, 0, 2> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
// The tutorial's three nested cubic sub-prisms, with sturm.
prism { linear_sweep cubic_spline 0, 0.8, 18,
  <3,-5>, <3,5>, <-5,0>, <3,-5>, <3,5>, <-5,0>,
  <2,-4>, <2,4>, <-4,0>, <2,-4>, <2,4>, <-4,0>,
  <1,-3>, <1,3>, <-3,0>, <1,-3>, <1,3>, <-3,0>
  sturm scale <0.22, 1, 0.22> rotate y*90 translate <1.6, 0, 2.2> pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
// A bezier drop, open (no caps).
prism { bezier_spline 0, 1.2, 8,
  <0,0>, <1.2,0.2>, <0.8,1.4>, <0,1.6>,
  <0,1.6>, <-0.8,1.4>, <-1.2,0.2>, <0,0>
  open translate <4.2, 0, 1.8> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
// A pyramid and a ziggurat by conic_sweep.
prism { conic_sweep linear_spline 0, 1, 5, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1>
  rotate x*180 translate y scale <0.8, 1.6, 0.8> translate <-3.4, 0, -1.2> pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
prism { conic_sweep quadratic_spline 0.25, 1, 6, <0,-1>, <1,0>, <0,1>, <-1,0>, <0,-1>, <1,0>
  rotate x*180 translate y scale <0.9, 1.2, 0.9> translate <-1, 0, -1.4> pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny } }
// A star cut by a box.
difference {
  prism { linear_spline -0.5, 0.5, 11,
    <0,1>, <0.22,0.3>, <0.95,0.31>, <0.36,-0.12>, <0.59,-0.81>, <0,-0.38>,
    <-0.59,-0.81>, <-0.36,-0.12>, <-0.95,0.31>, <-0.22,0.3>, <0,1> }
  box { <-0.3, 0, -2>, <2, 1, 2> }
  scale 1.1 rotate <-60, 0, 0> translate <1.4, 1, -1.2> pigment { color rgb <1, 0.6, 0.3> } finish { Shiny } }
object { Povray_Logo scale 1.3 translate <3.8, 0.8, -1.1> pigment { color rgb <0.95, 0.95, 0.95> } finish { Shiny } }
