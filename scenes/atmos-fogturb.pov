// atmos-fogturb.pov: fog stirred by turbulence (a vector amount,
// turb_depth, octaves, omega, lambda), constant and ground fog.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -6>
  right x*image_width/image_height
  look_at <0, 1, 4>
  angle 60
}

light_source { <-5, 10, -8> color rgb 1 }

plane { y, 0 pigment { color rgb <0.6, 0.55, 0.5> } }
plane { z, 20 pigment { color rgb <0.2, 0.3, 0.6> } hollow }

sphere { <-2, 1, 2>, 1 pigment { color rgb <0.9, 0.2, 0.1> } }
sphere { <2, 1, 8>, 1 pigment { color rgb <0.2, 0.8, 0.3> } }

fog {
  distance 10
  color rgb <0.8, 0.8, 0.85>
  turbulence <0.6, 1.2, 0.9>
  turb_depth 0.7
  octaves 4
  omega 0.6
  lambda 2.2
}
fog { fog_type 2 distance 2 fog_offset 0.3 fog_alt 0.4 color rgb <0.7, 0.6, 0.5> turbulence 1.5 }
