// obj-polygon.pov: polygons: the manual's letter P (a sub-polygon makes
// the hole), its triangle with three holes and three islands, one left
// open (closed for us, with a warning in both renderers), a non-planar
// one (projected on the plane of its first three points) and one in 3-D.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> right x*image_width/image_height look_at <0, 1.2, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1,0>, <0, 0>, <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>
  scale 0.45 translate <-4.2, 0.2, 1> pigment { color rgb <0.9, 0.3, 0.2> } }
polygon { 28,
  <0, 0> <1, 0> <0, 1> <0, 0> <.3, .7> <.4, .7> <.3, .8> <.3, .7> <.5, .5> <.6, .5> <.5, .6> <.5, .5>
  <.7, .3> <.8, .3> <.7, .4> <.7, .3> <.5, .2> <.6, .2> <.5, .3> <.5, .2> <.2, .5> <.3, .5> <.2, .6> <.2, .5>
  <.1, .1> <.2, .1> <.1, .2> <.1, .1>
  scale 2.8 rotate y*20 translate <-1.8, 0.1, 0.5> pigment { color rgb <0.3, 0.8, 0.3> } }
polygon { 5, <0,0>, <1,0>, <1.3,0.8>, <0.5,1.4>, <-0.3,0.8>
  scale 1.5 rotate x*70 translate <2, 0.05, -1.5> pigment { color rgb <0.2, 0.4, 0.9> } }
polygon { 5, <0,0,0>, <1.5,0,0.3>, <1.5,1.5,0.6>, <0,1.5,0.3>, <0,0,0>
  rotate y*-30 translate <2.3, 0.3, 1.5> pigment { color rgb <0.9, 0.8, 0.2> } }
polygon { 5, <0,0,0>, <1,0,0>, <1,1,0.2>, <0,1,0>, <0,0,0>
  scale 1.4 rotate y*50 translate <-0.5, 0.2, -1.8> pigment { color rgb <0.8, 0.4, 0.8> } }
