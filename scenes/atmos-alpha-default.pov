// atmos-alpha-default.pov: with +UA and no background statement the
// background is transparent (alpha 0), as in POV-Ray 3.7.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -5>
  right x*image_width/image_height
  look_at <0, 1, 0>
}

light_source { <-5, 10, -8> color rgb 1 }

sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.6, 0.2> } }
