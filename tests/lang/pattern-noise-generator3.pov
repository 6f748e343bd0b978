// noise_generator 3 (Perlin's gradient noise) as POV-Ray has it: bozo and
// f_noise_generator at points near and far from the origin, the patterns
// built on it (granite, wrinkles, marble's turbulence, agate), and the
// turbulence warp, which takes no notice of the generator.
#version 3.7;
global_settings { assumed_gamma 1 }
#include "functions.inc"
#declare B = function { pattern { bozo noise_generator 3 } }
#declare G = function { pattern { granite noise_generator 3 } }
#declare W = function { pattern { wrinkles noise_generator 3 } }
#declare M = function { pattern { marble turbulence 0.5 noise_generator 3 } }
#declare A = function { pattern { agate noise_generator 3 } }
#declare T = function { pattern { function { x } turbulence <0.1, 0.1, 0.1> octaves 3 noise_generator 3 } }
#declare Pts = array[6] { <0.3, 0.7, 1.1>, <-1.25, 0.4, 2.3>, <0.05, -0.6, -0.35>, <2.7, 1.3, -0.8>,
  <-123.456, 78.9, 1500.25>, <2047.5, -2048.25, 4096.75> }
#for (I, 0, 5)
  #declare P = Pts[I];
  #debug concat(str(B(P.x, P.y, P.z), 0, 9), " ", str(f_noise_generator(P.x, P.y, P.z, 3), 0, 9), " ",
    str(G(P.x, P.y, P.z), 0, 9), " ", str(W(P.x, P.y, P.z), 0, 9), "\n")
  #debug concat(str(M(P.x, P.y, P.z), 0, 9), " ", str(A(P.x, P.y, P.z), 0, 9), " ",
    str(T(P.x, P.y, P.z), 0, 9), "\n")
#end
