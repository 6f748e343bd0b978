// cam-normal-facets.pov: camera ray perturbation by the facets normal, in
// its coords form (crackle cells of 0.06 in the image plane (u, v, 0),
// each turning its rays by 0.12 x DNoise at its feature point, across d).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
camera {
  location <0, 1.5, -4> look_at <0, 1, 2> angle 55
  normal { facets coords 0.12 size 0.06 }
}
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
cylinder { <1.8, 0, 1>, <1.8, 2.2, 1>, 0.3 pigment { color rgb <0.3, 0.8, 0.4> } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
