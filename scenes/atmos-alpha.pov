// atmos-alpha.pov: with +UA, a background the scene sets is opaque in
// POV-Ray 3.7 (alpha 1 on every pixel), and a fog over it blends as usual.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -5>
  right x*image_width/image_height
  look_at <0, 1, 0>
}

light_source { <-5, 10, -8> color rgb 1 }

background { color rgb <0.2, 0.3, 0.5> }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.6, 0.2> } }
fog { distance 15 color rgb <0.6, 0.6, 0.6> }
