// lathe.pov: the manual's thick cylinder (linear), a quadratic vase, a
// cubic bottle and a bezier goblet.
#version 3.7;
#declare Stage_From = <0, 3.5, -6.5>;
#declare Stage_At = <0, 0.8, 0.3>;
#include "stage.inc"

lathe { linear_spline 5, <2, 0>, <3, 0>, <3, 5>, <2, 5>, <2, 0>
  scale 0.2 translate <-2.6, 0, 0.5> texture { T_Red } }
lathe { quadratic_spline 6, <0,-1>, <0,0>, <0.8,0.2>, <0.35,0.9>, <0.6,1.5>, <0,1.8>
  translate <-0.9, 0, 0.3> texture { T_Green } }
lathe { cubic_spline 8, <0,-0.5>, <0,0>, <0.7,0.15>, <0.3,0.7>, <0.55,1.2>, <0.2,1.7>, <0,1.8>, <0,2.3>
  sturm translate <0.8, 0, 0.3> texture { T_Blue } }
lathe { bezier_spline 16,
  <0,0>, <0.5,0>, <0.6,0.08>, <0.08,0.25>,
  <0.08,0.25>, <0.04,0.6>, <0.04,0.9>, <0.08,1.05>,
  <0.08,1.05>, <0.75,1.12>, <0.7,1.8>, <0.65,1.95>,
  <0.65,1.95>, <0.5,1.65>, <0.45,1.28>, <0,1.2>
  translate <2.5, 0, 0.4> texture { T_Gold } }
