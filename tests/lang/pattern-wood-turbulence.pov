// wood's own turbulence: x and y move by sin(2 pi T (x + D.x)) and
// sin(2 pi T (y + D.y)), D the vector turbulence (any generator), T the
// amount; with octaves, omega, lambda, per-axis amounts, generators 1 and
// 3, a transformation and the wave modifiers.
#version 3.7;
global_settings { assumed_gamma 1 }
#declare F0 = function { pattern { wood turbulence 0.02 octaves 1 } }
#declare F1 = function { pattern { wood turbulence 0.3 } }
#declare F2 = function { pattern { wood turbulence <0.05, 0.2, 0.7> octaves 3 omega 0.7 lambda 2.5 } }
#declare F3 = function { pattern { wood turbulence 0.5 noise_generator 1 } }
#declare F4 = function { pattern { wood turbulence 0.1 noise_generator 3 octaves 2 } }
#declare F5 = function { pattern { wood turbulence 1.3 scale 0.3 } }
#declare F6 = function { pattern { wood turbulence 0.2 ramp_wave frequency 2 } }
#declare Pts = array[4] { <0.3, 0.7, 1.1>, <-1.25, 0.4, 2.3>, <0.05, -0.6, -0.35>, <2.7, 1.3, -0.8> }
#for (I, 0, 3)
  #declare P = Pts[I];
  #debug concat(str(F0(P.x, P.y, P.z), 0, 9), " ", str(F1(P.x, P.y, P.z), 0, 9), " ",
    str(F2(P.x, P.y, P.z), 0, 9), " ", str(F3(P.x, P.y, P.z), 0, 9), "\n")
  #debug concat(str(F4(P.x, P.y, P.z), 0, 9), " ", str(F5(P.x, P.y, P.z), 0, 9), " ",
    str(F6(P.x, P.y, P.z), 0, 9), "\n")
#end
