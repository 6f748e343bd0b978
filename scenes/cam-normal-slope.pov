// cam-normal-slope.pov: a camera normal with a slope_map. POV-Ray's slope
// map is a cubic Hermite curve in each interval whose end slopes count per
// unit of the interval (t from 0 to 1), not per unit of the pattern value:
// an interval half as wide has half the slope. Top rows: gradient x,
// three entries; the map ends at 0.8, so the last fifth is flat.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
camera {
  location <0, 1.5, -4> look_at <0, 1, 2> angle 55
  normal { gradient x 0.7 slope_map { [0 <0, 1>] [0.3 <1, 0>] [0.8 <0, -1>] } scale 0.25 rotate 15*z }
}
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
cylinder { <1.8, 0, 1>, <1.8, 2.2, 1>, 0.3 pigment { color rgb <0.3, 0.8, 0.4> } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
