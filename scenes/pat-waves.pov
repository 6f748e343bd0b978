// pat-waves.pov: ripples and waves, as pigments (with frequency and phase,
// which they use inside their sines as well as on the value) and as
// normals, with POV-Ray's 10 wave sources.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <-8, 5, -4> color rgb 1 }
#declare M = color_map { [0 rgb <0.05, 0.15, 0.4>] [0.5 rgb <0.4, 0.7, 0.9>] [1 rgb 1] }
#macro B(T, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> texture { T } translate <X, 0, Z> }
#end
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.02 }
B(texture { pigment { ripples color_map { M } scale 0.5 } finish { F } }, -2.6, 1.3)
B(texture { pigment { waves color_map { M } scale 0.4 translate <0.3, 0, 0.2> } finish { F } }, 0, 1.3)
B(texture { pigment { ripples frequency 2 phase 0.3 color_map { M } scale 0.7 } finish { F } }, 2.6, 1.3)
B(texture { pigment { rgb 0.8 } normal { ripples 0.8 scale 0.3 } finish { F } }, -2.6, -1.3)
B(texture { pigment { rgb 0.8 } normal { waves 1.2 frequency 0.7 phase 0.2 scale 0.25 } finish { F } }, 0, -1.3)
B(texture { pigment { waves frequency 1.5 color_map { M } scale 0.5 } normal { waves 0.6 scale <0.5, 1, 0.3> } finish { F } }, 2.6, -1.3)
