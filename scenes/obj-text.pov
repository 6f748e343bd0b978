// obj-text.pov: text objects. POV-Ray's own fonts (timrom, cyrvetic,
// crystal: found in the system's fonts when Debian's fonts-povray is
// installed), kerning ("AV", "To"), an offset between characters, a
// text cut out of a box (CSG) and a rotated one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 2.2, -6> right x*image_width/image_height look_at <0, 0.9, 0> angle 52 }
light_source { <4, 9, -8> color rgb 1 }
light_source { <-6, 4, -5> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.5 phong_size 30 }

text { ttf "timrom.ttf" "AVTo Wag" 0.3, 0
  scale 0.9 translate <-2.6, 1.9, 0> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
text { ttf "cyrvetic.ttf" "Kerning" 0.5, <0.05, 0.03, 0>
  scale 0.8 translate <-2.6, 1.0, 0> pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }
text { internal 3 "12:45" 0.4, 0
  scale 0.8 translate <0.6, 1.0, 0> pigment { color rgb <0.2, 0.5, 0.9> } finish { Shiny } }
difference {
  box { <-0.1, -0.25, 0.05>, <2.4, 0.95, 0.5> }
  text { ttf "timrom.ttf" "Cut" 1, 0 translate <0.05, 0, -0.2> }
  pigment { color rgb <0.9, 0.8, 0.3> } finish { Shiny }
  translate <-2.6, 0.3, 0.5>
}
text { ttf "timrom.ttf" "&g?" 0.6, 0
  rotate <0, -35, 0> translate <0.9, 0.02, -0.6> pigment { color rgb <0.8, 0.4, 0.9> } finish { Shiny } }
