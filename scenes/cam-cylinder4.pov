// cam-cylinder4.pov: cylinder 4: horizontal cylinder, the viewpoint moves along right.
// The same small world for every camera test (tests/render/cameras.list).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.55, 0.7, 0.9> }
light_source { <-20, 40, -30> color rgb 1 }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.85> color rgb <0.25, 0.3, 0.55> } }
sphere { <0, 1, 3>, 1 pigment { checker color rgb <1, 0.25, 0.1> color rgb <1, 0.95, 0.4> scale 0.25 } finish { phong 0.5 } }
sphere { <-2.6, 0.7, 4.5>, 0.7 pigment { color rgb <0.2, 0.8, 0.3> } }
box { <1.8, 0, 1>, <2.8, 1.5, 2> pigment { color rgb <0.3, 0.5, 1> } }
cylinder { <3, 0, -3>, <3, 2.5, -3>, 0.4 pigment { color rgb <0.9, 0.5, 0.9> } }
sphere { <-2, 1, -5>, 0.8 pigment { checker color rgb <0.1, 0.1, 0.1> color rgb 1 scale 0.3 } }
camera { cylinder 4 location <0, 1.5, -1.5> right 6*x look_at <0, 1.5, 3> angle 120 }
