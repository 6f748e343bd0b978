// pat-pavement.pov: six pavements on the tops of six boxes seen from above:
// triangles, squares and hexagons, with pointy, cut and rounded corners.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <3, 12, -6> color rgb 1 }
#declare M = color_map { [0 rgb <0.2, 0.3, 0.6>] [0.5 rgb <0.85, 0.75, 0.5>] [0.8 rgb <0.6, 0.2, 0.1>] [1 rgb 0.05] }
#macro B(P, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { P color_map { M } scale 0.3 rotate y*10 }
        finish { ambient 0.2 diffuse 0.8 } translate <X, 0, Z> }
#end
B(pigment { pavement number_of_sides 3 number_of_tiles 5 pattern 3 }, -2.6, 1.3)
B(pigment { pavement number_of_sides 3 number_of_tiles 6 pattern 8 exterior 2 form 1 interior 1 }, 0, 1.3)
B(pigment { pavement number_of_sides 4 number_of_tiles 4 pattern 5 form 2 }, 2.6, 1.3)
B(pigment { pavement number_of_sides 4 number_of_tiles 6 pattern 20 exterior 1 interior 2 }, -2.6, -1.3)
B(pigment { pavement number_of_sides 6 number_of_tiles 3 pattern 2 form 1 }, 0, -1.3)
B(pigment { pavement number_of_sides 6 number_of_tiles 5 pattern 13 form 2 interior 2 }, 2.6, -1.3)
