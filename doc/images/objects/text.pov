// text.pov: text in timrom.ttf extruded 0.3 deep, kerned, and a box with a
// word cut out of it.
#version 3.7;
#declare Stage_From = <0, 3.2, -7>;
#declare Stage_At = <0, 0.9, 0>;
#include "stage.inc"

text { ttf "timrom.ttf" "lucent" 0.3, 0 scale 1.1 translate <-2.7, 1.3, 0> texture { T_Gold } }
difference {
  box { <-0.1, -0.25, 0.05>, <2.2, 0.95, 0.5> }
  text { ttf "timrom.ttf" "Cut" 1, 0 translate <0.1, 0, -0.2> }
  translate <0.3, 0.01, 0> texture { T_Blue }
}
text { ttf "cyrvetic.ttf" "AVo" 0.5, <0.05, 0, 0> scale 0.8 translate <-2.6, 0.01, -0.8> texture { T_Red } }
