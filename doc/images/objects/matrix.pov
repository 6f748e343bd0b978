// matrix.pov: a box sheared by matrix (x grows with y), and the same
// marker turned by a matrix that equals rotate y*90.
#version 3.7;
#include "stage.inc"

box { <-0.5, 0, -0.5>, <0.5, 1.5, 0.5>
  matrix < 1,   0, 0,
           0.6, 1, 0,
           0,   0, 1,
          -1.8, 0, 0 >
  texture { T_Red } }
union {
  box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> }
  sphere { <0.4, 0.8, -0.4>, 0.2 texture { T_Red } }
  texture { T_Blue }
  matrix < 0, 0, -1,
           0, 1, 0,
           1, 0, 0,
           1.3, 0, 0 >
}
