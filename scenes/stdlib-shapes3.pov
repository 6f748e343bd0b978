// stdlib-shapes3.pov: a swatch of shapes3.inc, shapes.inc's Supertorus
// and meshmaker.inc: segments, columns and pyramids, faceted and round
// eggs, rounded frames and tubes, a supertorus, and meshes from Lathe,
// Coons and Parametric.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes3.inc"
#include "meshmaker.inc"
camera { location <0, 6.5, -9.5> right x*image_width/image_height look_at <0, 0.5, 0.6> angle 52 }
light_source { <6, 14, -8> color rgb 1 }
light_source { <-8, 7, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare F = finish { phong 0.5 phong_size 30 }
#macro Put(O, P, C) object { O translate P pigment { color rgb C } finish { F } } #end
// Back row.
Put(object { Segment_of_Torus(0.8, 0.25, 240) translate y * 0.25 }, <-5, 0, 3>, <0.9, 0.3, 0.2>)
Put(object { Segment_of_CylinderRing(0.9, 0.6, 0.6, 120) }, <-2.8, 0, 3>, <0.3, 0.8, 0.3>)
Put(object { Column_N(6, 0.6, 1.4) }, <-0.9, 0, 3>, <0.2, 0.4, 0.9>)
Put(object { Pyramid_N(5, 0.8, 0.3, 1.5) }, <0.9, 0, 3>, <0.9, 0.8, 0.2>)
Put(object { Facetted_Egg(3, 8) scale 0.8 }, <2.7, 0, 3>, <0.8, 0.4, 0.8>)
Put(object { Egg scale 0.8 }, <4.5, 0, 3>, <0.2, 0.8, 0.8>)
// Middle row.
Put(object { Round_Pyramid_N_out(6, <0,0,0>, 0.8, <0,1.4,0>, 0.4, 0.08, 1, 0) }, <-4.5, 0, 0.6>, <0.9, 0.6, 0.3>)
Put(object { Round_Pyramid_N_in(5, <0,0,0>, 0.7, <0,1.3,0>, 0.3, 0.08, 0, 0) }, <-2.5, 0, 0.6>, <0.6, 0.9, 0.4>)
Put(object { Rounded_Tube(0.8, 0.5, 0.1, 0.8, 0) }, <-0.5, 0, 0.6>, <0.4, 0.6, 0.9>)
Put(object { Round_Conic_Torus(0.8, 0.3, 0.5, 0.1, 0) translate y * 0.6 }, <1.4, 0, 0.6>, <0.9, 0.9, 0.4>)
Put(object { Half_Hollowed_Rounded_Cylinder2(1.8, 0.6, 0.15, 0.08, 1.5, 0) translate y * 0.6 }, <3.5, 0, 0.6>, <0.9, 0.5, 0.7>)
// Front row.
Put(object { Supertorus(0.7, 0.25, 0.4, 0.4, 0.001, 4) translate y * 0.25 }, <-4, 0, -1.8>, <0.9, 0.4, 0.3>)
#declare S = spline { cubic_spline -0.25, <0.1, -0.2, 0>, 0, <0.3, 0, 0>, 0.3, <0.7, 0.3, 0>, 0.6, <0.3, 0.8, 0>, 1, <0.45, 1.2, 0>, 1.25, <0.6, 1.4, 0> }
Put(object { Lathe(S, 12, 360, 16, "") }, <-1.6, 0, -1.8>, <0.4, 0.8, 0.5>)
#declare S1 = spline { cubic_spline -0.5, <-0.5, 0, 0>, 0, <0, 0, 0>, 0.5, <0.6, 0.4, 0>, 1, <1.2, 0, 0>, 1.5, <1.7, 0, 0> }
#declare S2 = spline { linear_spline 0, <1.2, 0, 0>, 1, <1.2, 0, 1.2> }
#declare S3 = spline { cubic_spline -0.5, <1.7, 0, 1.2>, 0, <1.2, 0, 1.2>, 0.5, <0.6, 0.7, 1.2>, 1, <0, 0, 1.2>, 1.5, <-0.5, 0, 1.2> }
#declare S4 = spline { linear_spline 0, <0, 0, 1.2>, 1, <0, 0, 0> }
Put(object { Coons(S1, S2, S3, S4, 10, 10, "") translate <-0.6, 0.05, -0.6> }, <0.7, 0, -1.8>, <0.5, 0.5, 0.9>)
#declare F1 = function(u, v) { cos(u) * (0.6 + 0.2*cos(v)) }
#declare F2 = function(u, v) { 0.2*sin(v) }
#declare F3 = function(u, v) { sin(u) * (0.6 + 0.2*cos(v)) }
Put(object { Parametric(F1, F2, F3, <0, 0>, <2*pi, 2*pi>, 24, 12, "") rotate x*30 translate y*0.55 }, <3.4, 0, -1.8>, <0.9, 0.7, 0.3>)
