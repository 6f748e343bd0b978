// pat-tiling.pov: tilings 3, 5, 13, 17, 19 and 22 on the tops of six boxes seen
// from above, each through a colour map that shows every tile type and its bevel.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.9, 0.8, 0.5>] [0.3 rgb <0.2, 0.3, 0.7>] [0.5 rgb <0.8, 0.2, 0.1>]
                         [0.7 rgb <0.1, 0.6, 0.3>] [0.85 rgb 1] [1 rgb 0] }
#macro B(N, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { tiling N color_map { M } scale 0.35 rotate y*10 }
        finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(3, -2.6, 1.3) B(5, 0, 1.3) B(13, 2.6, 1.3)
B(17, -2.6, -1.3) B(19, 0, -1.3) B(22, 2.6, -1.3)
