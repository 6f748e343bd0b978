// bench-mesh2.pov: the million-triangle benchmark: a ~38 MB mesh2 (a
// rippled height field of 999,698 triangles, written by gen-mesh2.sh into
// mesh1m.inc at bench time), placed once and seen whole.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "mesh1m.inc"
camera { location <0, 1.6, -2.2> right x*image_width/image_height look_at <0, 0, 0> angle 55 }
light_source { <3, 6, -4> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }
object { Bench_Mesh pigment { color rgb <0.8, 0.7, 0.5> } finish { phong 0.4 } }
