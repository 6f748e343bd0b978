// normal-slope.pov: the numerical slope of normal patterns that have no
// perturbation of their own (texture_eval.c, slope_normal): tilted in the
// pattern's space by 2/15 of the amount times the height's gradient, so
// non-uniform scales stretch the tilt. Top row: gradient x under scale
// <0.5, 1.5, 1>; wood scaled <0.2, 0.6, 0.2>; a slope_map (slopes per unit
// of each segment). Bottom row: bozo with warp { turbulence }; bozo with
// classic turbulence; marble with turbulence, a slope_map and a rotation.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 0, -10> look_at 0 angle 36 }
light_source { <-6, 8, -10>, rgb 1 }
background { rgb 0.2 }
#declare F = finish { ambient 0.1 diffuse 0.8 specular 0.4 }
#declare B = sphere { 0, 0.95 pigment { rgb 0.8 } finish { F } }
object { B normal { gradient x 1 scale <0.5, 1.5, 1> } translate <-2.1, 1, 0> }
object { B normal { wood 0.6 scale <0.2, 0.6, 0.2> } translate <0, 1, 0> }
object { B normal { gradient x 1 slope_map { [0 <0, 1>] [0.5 <1, 0>] [1 <0, -1>] } scale <0.3, 0.9, 0.3> } translate <2.1, 1, 0> }
object { B normal { bozo 0.8 scale 0.2 warp { turbulence 0.3 } } translate <-2.1, -1, 0> }
object { B normal { bozo 0.8 turbulence 0.3 scale 0.2 } translate <0, -1, 0> }
object { B normal { marble 1 slope_map { [0 <0, 0>] [0.3 <0.5, 2>] [1 <1, 0>] } turbulence 0.5 scale 0.5 rotate 20*z } translate <2.1, -1, 0> }
