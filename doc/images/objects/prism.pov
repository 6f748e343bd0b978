// prism.pov: a linear prism with a hole (two sub-prisms), the manual's
// quadratic frame, a cubic drop, a bezier leaf, and a conic pyramid.
#version 3.7;
#declare Stage_From = <0, 4, -6.5>;
#declare Stage_At = <0, 0.4, 0.3>;
#include "stage.inc"

prism { linear_spline 0, 0.5, 10,
  <0,0>, <1.2,0>, <1.2,1>, <0,1>, <0,0>,
  <0.3,0.3>, <0.9,0.3>, <0.9,0.7>, <0.3,0.7>, <0.3,0.3>
  translate <-2.9, 0, 0.6> texture { T_Red } }
prism { quadratic_spline 0, 0.7, 12,
  <1,-1>, <0,0>, <6,0>, <6,8>, <0,8>, <0,0>,
  <2,0>, <1,1>, <5,1>, <5,7>, <1,7>, <1,1>
  scale <0.18, 1, 0.15> translate <-0.9, 0, 0.6> texture { T_Green } }
prism { cubic_spline 0, 0.9, 6,
  <3,-5>, <3,5>, <-5,0>, <3,-5>, <3,5>, <-5,0>
  scale 0.13 scale <1, 1/0.13, 1> translate <1.1, 0, 1.3> texture { T_Blue } }
prism { bezier_spline 0, 0.3, 8,
  <0,0>, <0.9,0.2>, <0.8,1.1>, <0,1.4>,
  <0,1.4>, <-0.8,1.1>, <-0.9,0.2>, <0,0>
  rotate y*-40 translate <2.3, 0, -0.4> texture { T_Gold } }
prism { conic_sweep linear_spline 0, 1, 5, <1,1>, <-1,1>, <-1,-1>, <1,-1>, <1,1>
  rotate x*180 translate y scale <0.6, 1.3, 0.6> translate <-0.6, 0, -0.9> texture { T_Violet } }
