// blob.pov: the manual's three spheres, each with its own texture; a cross of
// cylinders dented by a negative sphere; ellipsoidal components.
#version 3.7;
#declare Stage_From = <0, 3.5, -6.5>;
#declare Stage_At = <0, 0.9, 0.3>;
#include "stage.inc"

blob { threshold 0.45
  sphere { <0.75, 0, 0>, 1, 1 texture { T_Red } }
  sphere { <-0.375, 0.64952, 0>, 1, 1 texture { T_Green } }
  sphere { <-0.375, -0.64952, 0>, 1, 1 }
  texture { T_Blue }
  scale 0.8 rotate x*90 translate <-2, 0.6, 0.6> }
blob { threshold 0.5
  cylinder { <-0.9, 0, 0>, <0.9, 0, 0>, 0.55, 1 }
  cylinder { <0, 0, -0.9>, <0, 1.5, 0.4>, 0.5, strength 1.2 }
  sphere { <0.3, 0.4, -0.3>, 0.6, -1.5 }
  texture { T_Gold } translate <0, 0.55, 0.6> }
blob { threshold 0.4
  sphere { 0, 1, 1 scale <1.2, 0.5, 0.7> rotate z*30 }
  sphere { 0, 1, 1 scale <0.5, 1.2, 0.5> rotate x*-25 translate <0.4, 0.5, 0> texture { T_White } }
  component 0.8, 0.7, <-0.7, 0.3, 0>
  sturm texture { T_Violet } translate <2.2, 0.8, 0.3> }
