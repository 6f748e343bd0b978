// obj-lathe.pov: lathes. Every spline (linear: the manual's thick
// cylinder; quadratic; cubic with sturm; bezier: a goblet), a lathe in CSG
// (a difference with a box) and one scaled and turned.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> right x*image_width/image_height look_at <0, 1.2, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>, <2, 0>
  scale 0.3 translate <-3.5, 0, 2> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
lathe { quadratic_spline 6, <0,-1>, <0,0>, <1.2,0.3>, <0.5,1.2>, <0.9,2.2>, <0,2.6>
  translate <-1.2, 0, 2> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
lathe { cubic_spline 8, <0,-0.5>, <0,0>, <1,0.2>, <0.4,0.9>, <0.8,1.6>, <0.3,2.2>, <0,2.4>, <0,3>
  sturm translate <1.2, 0, 2> pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
lathe { bezier_spline 16,
  <0,0>, <0.6,0>, <0.8,0.1>, <0.1,0.3>,
  <0.1,0.3>, <0.05,0.8>, <0.05,1.2>, <0.1,1.4>,
  <0.1,1.4>, <1,1.5>, <0.9,2.4>, <0.85,2.6>,
  <0.85,2.6>, <0.7,2.2>, <0.6,1.7>, <0,1.6>
  translate <3.5, 0, 2> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
difference {
  lathe { linear_spline 4, <0,0>, <1.2,0>, <0.4,1.5>, <0,1.5> }
  box { <0, -1, -2>, <2, 2, 0> }
  rotate y*-30 translate <-2, 0, -1.5> pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
lathe { quadratic_spline 5, <1,-1>, <0.6,0>, <1,0.5>, <0.6,1>, <1,1.5>
  scale <1, 0.8, 1> rotate z*60 translate <1.8, 1.2, -1.2> pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny } }
