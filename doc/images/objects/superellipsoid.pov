// superellipsoid.pov: <e, n> = <0.2, 0.2>, <1, 0.3>, <0.3, 1>, <1, 1> and <2, 2>.
#version 3.7;
#declare Stage_From = <0, 3, -7>;
#declare Stage_At = <0, 0.6, 0>;
#include "stage.inc"

superellipsoid { <0.2, 0.2> scale 0.5 rotate y*30 translate <-2.4, 0.5, 0> texture { T_Red } }
superellipsoid { <1, 0.3> scale 0.5 rotate y*30 translate <-1.2, 0.5, 0> texture { T_Gold } }
superellipsoid { <0.3, 1> scale 0.5 rotate y*30 translate <0, 0.5, 0> texture { T_Green } }
superellipsoid { <1, 1> scale 0.5 translate <1.2, 0.5, 0> texture { T_Blue } }
superellipsoid { <2, 2> scale 0.5 rotate y*30 translate <2.4, 0.5, 0> texture { T_Violet } }
