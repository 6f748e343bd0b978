// merge.pov: the same two spheres as a union (left) and as a merge
// (right), both cut open by clipped_by: the merge has no inner walls.
#version 3.7;
#include "stage.inc"

#declare Left = sphere { <-0.4, 0, 0>, 0.6 }
#declare Right = sphere { <0.4, 0, 0>, 0.6 }
union { object { Left } object { Right }
  clipped_by { plane { -z, 0 } }
  texture { T_Green } translate <-1.3, 0.6, 0> }
merge { object { Left } object { Right }
  clipped_by { plane { -z, 0 } }
  texture { T_Green } translate <1.3, 0.6, 0> }
