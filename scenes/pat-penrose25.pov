// pat-penrose25.pov: POV-Ray's tiling 25, Penrose's pentagons, stars,
// boats and diamonds, on the tops of boxes seen from above: near the
// origin (five-fold symmetric about it) and far from it, scaled and turned.
// Each of the six kinds of tile has its colour band, dark at its edges.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map {
  [0 rgb <0.2, 0.3, 0.6>] [0.13 rgb <0.3, 0.4, 0.7>] [1/6 rgb 0.05]
  [1/6 rgb <0.2, 0.6, 0.3>] [0.3 rgb <0.3, 0.7, 0.4>] [2/6 rgb 0.05]
  [2/6 rgb <0.7, 0.6, 0.2>] [0.46 rgb <0.8, 0.7, 0.3>] [3/6 rgb 0.05]
  [3/6 rgb <0.8, 0.3, 0.2>] [0.63 rgb <0.9, 0.4, 0.3>] [4/6 rgb 0.05]
  [4/6 rgb <0.6, 0.3, 0.7>] [0.8 rgb <0.7, 0.4, 0.8>] [5/6 rgb 0.05]
  [5/6 rgb <0.9, 0.9, 0.85>] [0.96 rgb 1] [1 rgb 0.05] }
#macro B(P, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { P color_map { M } }
        finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(pigment { tiling 25 scale 0.3 }, -2.6, 1.3)
B(pigment { tiling 25 scale 0.15 }, 0, 1.3)
B(pigment { tiling 25 translate <-40, 0, 25> scale 0.3 }, 2.6, 1.3)
B(pigment { tiling 25 translate <900, 0, -700> scale 0.2 }, -2.6, -1.3)
B(pigment { tiling 25 scale 0.2 rotate y*20 }, 0, -1.3)
B(pigment { tiling 25 scale 0.5 rotate y*-30 }, 2.6, -1.3)
