// mat-patterns.pov: a checker floor, a marble sphere with turbulence, a glass sphere
// and a wood sphere with a bumps normal: patterns, colour maps, noise and
// normals through the whole shading path.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 45 }
light_source { <5, 10, -8> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb <0.2, 0.3, 0.6> } }
sphere { <-1.3, 1, 0>, 1 pigment { marble color_map { [0 rgb <0.9,0.8,0.7>] [1 rgb <0.5,0.1,0.1>] } turbulence 0.6 scale 0.5 } finish { phong 0.5 } }
sphere { <1.3, 1, 0>, 1 pigment { rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.1 phong 0.8 } interior { ior 1.5 } }
sphere { <0, 0.5, -1.5>, 0.5 pigment { wood scale 0.1 } normal { bumps 0.6 scale 0.1 } }
