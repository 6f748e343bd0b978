// obj-torus-poly.pov: tori and polynomial surfaces. Exercises torus
// (plain, rotated, with sturm, non-uniformly scaled), quartic (the same
// torus written as its 35 coefficients), cubic (a monkey saddle clipped by
// a sphere) and poly of order 6 (a rounded cube x^6 + y^6 + z^6 = 1,
// bounded by a box, with sturm).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 5, -10> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }

torus { 1, 0.3 translate <-3.5, 0.3, 1.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
torus { 0.8, 0.25 sturm rotate <70, 0, 20> translate <-1.2, 1.2, 2> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
torus { 0.7, 0.2 scale <1, 2.5, 0.6> translate <1.3, 0.5, 2> pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny } }
// (x^2+y^2+z^2 + R^2 - r^2)^2 - 4 R^2 (x^2+z^2) with R = 2, r = 0.5.
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, -8.5, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 2, 0, 7.5, 0, 0, 0, 0, 1, 0, -8.5, 0, 14.0625>
  scale 0.5 rotate x*-30 translate <3.6, 1, 1.5> pigment { color rgb <0.9, 0.8, 0.2> } finish { Shiny } }
// y = x^3 - 3 x z^2
cubic { <1, 0, 0, 0, 0, 0, 0, -3, 0, 0, 0, 0, 0, 0, 0, -1, 0, 0, 0, 0>
  clipped_by { sphere { 0, 0.9 } } translate <-2, 1, -1.5> pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
poly { 6, <1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,
           0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,0,1,0,0,0,0,0,-1>
  sturm bounded_by { box { -1.01, 1.01 } } scale 0.7 rotate y*30 translate <1, 0.7, -1.5>
  pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny } }
