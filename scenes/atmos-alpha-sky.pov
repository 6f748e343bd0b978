// atmos-alpha-sky.pov: with +UA, a background with transmit, a sky_sphere
// whose layers let part of it through, and a fog with transmit: the alpha
// is 1 minus what stays see-through after all of them, as in POV-Ray 3.7;
// a filtering sphere passes on its share of it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -6> look_at <0, 1.3, 0> angle 60 }
light_source { <-5, 8, -8> color rgb 1 }
background { rgbt <0.2, 0.3, 0.5, 0.6> }
sky_sphere {
  pigment { gradient y color_map { [0 rgbft <1, 0.8, 0.6, 0.2, 0.5>] [1 rgbt <0.2, 0.3, 0.9, 0.1>] } }
}
fog { distance 40 color rgbt <0.7, 0.7, 0.8, 0.5> }
sphere { <-1, 1, 0>, 1 pigment { rgbf <0.3, 1, 0.4, 0.7> } finish { phong 0.5 } }
sphere { <1.5, 0.8, 2>, 0.8 pigment { rgb <1, 0.6, 0.3> } }
