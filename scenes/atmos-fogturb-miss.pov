// atmos-fogturb-miss.pov: turbulent fogs on rays that hit nothing. POV-Ray
// takes such a ray to end about 2e10 away, where its noise saturates at 0
// or 1 (beyond the range of a 32-bit int), so the sky shows a few flat
// shades of fog in patches, not a smooth haze. A sphere and a ground plane
// for comparison, with their fog turbulent as usual.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -6>
  right x*image_width/image_height
  look_at <0, 1.6, 0>
  angle 70
}

light_source { <-5, 10, -8> color rgb 1 }
background { color rgb <0.1, 0.2, 0.6> }

plane { y, 0 pigment { color rgb <0.6, 0.55, 0.5> } }
sphere { <0.5, 1, 2>, 1 pigment { color rgb <0.9, 0.2, 0.1> } }

fog {
  distance 2e10
  color rgb <0.9, 0.8, 0.7>
  turbulence <0.8, 1.3, 0.5>
  turb_depth 0.6
  octaves 5
}
fog { fog_type 2 distance 4 fog_offset 0.5 fog_alt 1.5 color rgb <0.5, 0.6, 0.7> turbulence 1.2 }
