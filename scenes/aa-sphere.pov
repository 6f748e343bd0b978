// aa-sphere.pov: a checkered sphere over a plane, world-space checker, the
// plainest antialiasing check (+A0.3 without jitter, methods 1 and 2 in
// tests/render/sampling.list; aa-sphere-m2.pov includes this file).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> right x*image_width/image_height angle 50 }
light_source { <-5, 8, -6> color rgb 1 }
sphere { <0, 0.6, 0>, 1 pigment { checker color rgb <0.9, 0.2, 0.1> color rgb <0.1, 0.3, 0.8> scale 0.3 } }
plane { y, -0.4 pigment { color rgb 0.5 } }
