// pat-penrose.pov: POV-Ray's aperiodic tilings on the tops of boxes seen
// from above: Penrose's kites and darts (tiling 26) and rhombi (tiling 27),
// near the origin and far from it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.2, 0.3, 0.6>] [0.35 rgb <0.85, 0.75, 0.5>] [0.5 rgb 0.05]
                         [0.5 rgb <0.7, 0.25, 0.15>] [0.85 rgb <0.95, 0.9, 0.8>] [1 rgb 0.05] }
#macro B(P, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { P color_map { M } }
        finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(pigment { tiling 26 scale 0.3 }, -2.6, 1.3)
B(pigment { tiling 27 scale 0.3 }, 0, 1.3)
B(pigment { tiling 26 translate <-40, 0, 25> scale 0.3 }, 2.6, 1.3)
B(pigment { tiling 27 translate <90, 0, -70> scale 0.2 }, -2.6, -1.3)
B(pigment { tiling 26 scale 0.15 rotate y*20 }, 0, -1.3)
B(pigment { tiling 27 scale 0.5 rotate y*-30 }, 2.6, -1.3)
