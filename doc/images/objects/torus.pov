// torus.pov: a ring torus, a standing one solved with sturm, and a
// spindle torus (minor radius > major) cut open to show its inner part.
#version 3.7;
#include "stage.inc"

torus { 0.9, 0.3 translate <-1.7, 0.3, 0.8> texture { T_Red } }
torus { 0.7, 0.25 sturm rotate x*90 translate <0.1, 0.95, 1> texture { T_Green } }
torus { 0.4, 0.6 clipped_by { plane { -z, 0 } } rotate y*-30 translate <1.9, 0.6, 0> texture { T_Blue } }
