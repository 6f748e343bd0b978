// mesh.pov: a pyramid mesh with one gold face, declared once and placed
// three times (the three share one copy of the triangles and hierarchy).
#version 3.7;
#include "stage.inc"

#declare Pyramid = mesh {
  triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.4, 0> texture { T_Gold } }
  triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.4, 0> }
  triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.4, 0> }
  triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.4, 0> }
  inside_vector y
  texture { T_Blue }
}
object { Pyramid scale 0.6 rotate y*20 translate <-1.9, 0, 0> }
object { Pyramid rotate y*30 translate <0, 0, 0.6> }
object { Pyramid scale <0.6, 1.3, 0.6> rotate y*-15 translate <1.9, 0, 0> }
