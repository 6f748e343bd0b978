// mat-dispersion.pov: dispersion through a glass prism-like box and a
// sphere over a striped floor (dispersion and dispersion_samples).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3, -9> look_at <0, 1, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 9, -6> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
#declare I = 0;
#while (I < 20)
  box { <-10 + I, -1, -6>, <-9.5 + I, 0, 10> pigment { color rgb 1 } }
  box { <-9.5 + I, -1, -6>, <-9 + I, 0, 10> pigment { color rgb 0.05 } }
  #declare I = I + 1;
#end
box { <-0.7, -0.7, -0.7>, <0.7, 0.7, 0.7> rotate <20, 45, 0> translate <-1.5, 1.2, 0>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 dispersion 1.15 dispersion_samples 12 } }
sphere { <1.6, 1.1, 0>, 1.1 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.6 dispersion 1.1 } }
