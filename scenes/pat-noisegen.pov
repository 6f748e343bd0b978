// pat-noisegen.pov: global_settings { noise_generator 1 } as the generator of
// the patterns that name none (bozo, spotted, a turbulence warp), beside a
// bozo that names generator 2 and granite, which uses 2 when it says so.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 1 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.1, 0.1, 0.3>] [0.5 rgb <0.9, 0.7, 0.3>] [1 rgb 1] }
#macro B(P, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { P } finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(pigment { bozo color_map { M } scale 0.4 }, -2.6, 1.3)
B(pigment { granite noise_generator 2 color_map { M } scale 2 }, 0, 1.3)
B(pigment { bozo noise_generator 2 color_map { M } scale 0.4 }, 2.6, 1.3)
B(pigment { spotted color_map { M } scale 0.2 }, -2.6, -1.3)
B(pigment { gradient x color_map { M } warp { turbulence 0.5 } scale 0.6 }, 0, -1.3)
B(pigment { bumps color_map { M } scale 0.3 }, 2.6, -1.3)
