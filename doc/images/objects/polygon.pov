// polygon.pov: the manual's letter P (its second sub-polygon is the hole)
// and its triangle with three holes and three islands.
#version 3.7;
#declare Stage_From = <0, 2.5, -6.5>;
#declare Stage_At = <0, 1.1, 0>;
#include "stage.inc"

polygon { 12, <0, 0>, <0, 6>, <4, 6>, <4, 3>, <1, 3>, <1,0>, <0, 0>, <1, 4>, <1, 5>, <3, 5>, <3, 4>, <1, 4>
  scale 0.4 translate <-2.4, 0.05, 0.5> texture { T_Red } }
polygon { 28,
  <0, 0> <1, 0> <0, 1> <0, 0> <.3, .7> <.4, .7> <.3, .8> <.3, .7> <.5, .5> <.6, .5> <.5, .6> <.5, .5>
  <.7, .3> <.8, .3> <.7, .4> <.7, .3> <.5, .2> <.6, .2> <.5, .3> <.5, .2> <.2, .5> <.3, .5> <.2, .6> <.2, .5>
  <.1, .1> <.2, .1> <.1, .2> <.1, .1>
  scale 2.4 rotate y*-15 translate <0.2, 0.05, 0.5> texture { T_Green } }
