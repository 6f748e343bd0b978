// pat-cells.pov: crackle (default, metric 1 with an offset, F1 alone,
// solid) and cells on the tops of six boxes seen from above: POV-Ray's
// own feature points and cell values.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb 0.05] [0.1 rgb <0.9, 0.8, 0.5>] [0.5 rgb <0.6, 0.3, 0.2>] [1 rgb <0.2, 0.3, 0.6>] }
#macro B(P, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { P color_map { M } }
        finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(pigment { crackle scale 0.4 }, -2.6, 1.3)
B(pigment { crackle metric 1 offset 0.1 scale 0.4 }, 0, 1.3)
B(pigment { crackle form <1, 0, 0> scale 0.4 }, 2.6, 1.3)
B(pigment { crackle solid scale 0.4 }, -2.6, -1.3)
B(pigment { crackle metric 3 form <-1, 0.5, 0.5> scale 0.4 }, 0, -1.3)
B(pigment { cells scale 0.3 }, 2.6, -1.3)
