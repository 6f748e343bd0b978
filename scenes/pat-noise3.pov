// pat-noise3.pov: noise_generator 3 (Perlin's gradient noise) in pigments
// (bozo, granite, marble with turbulence, a turbulence warp) and normals
// (bumps, wrinkles), on the tops of boxes seen from above.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.1, 0.2, 0.5>] [0.5 rgb <0.9, 0.8, 0.5>] [1 rgb <0.6, 0.1, 0.1>] }
#macro B(T, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> texture { T } translate <X, 0, Z> }
#end
B(texture { pigment { bozo noise_generator 3 color_map { M } scale 0.3 } }, -2.6, 1.3)
B(texture { pigment { granite noise_generator 3 color_map { M } scale 2 } }, 0, 1.3)
B(texture { pigment { marble turbulence 0.8 noise_generator 3 color_map { M } scale 0.7 } }, 2.6, 1.3)
B(texture { pigment { gradient x noise_generator 3 warp { turbulence 0.6 octaves 4 } color_map { M } scale 0.8 } }, -2.6, -1.3)
B(texture { pigment { rgb <0.8, 0.7, 0.5> } normal { bumps 1.5 noise_generator 3 scale 0.2 } }, 0, -1.3)
B(texture { pigment { rgb <0.5, 0.7, 0.8> } normal { wrinkles 1 noise_generator 3 scale 0.4 } }, 2.6, -1.3)
