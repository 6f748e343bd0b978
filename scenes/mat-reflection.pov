// mat-reflection.pov: reflection blocks. Variable reflection with min and
// max and falloff, fresnel with the interior's ior, metallic reflection,
// exponent and reflection_exponent, conserve_energy on a filtering
// surface, over a floor of alternating boxes.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }
camera { location <0, 3.5, -10> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-5, 9, -7> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
#declare I = 0;
#while (I < 8)
  box { <-8 + 2*I, -1, -6>, <-6 + 2*I, 0, 8> pigment { color rgb (mod(I, 2) ? <0.8, 0.8, 0.7> : <0.2, 0.25, 0.3>) } }
  #declare I = I + 1;
#end
#declare P = pigment { color rgb <0.9, 0.6, 0.2> }
sphere { <-3.3, 0.7, 1.5>, 0.7 pigment { P } finish { diffuse 0.3 reflection { 0.05, 0.9 falloff 2 } } }
sphere { <-1.1, 0.7, 1.5>, 0.7 pigment { P } finish { diffuse 0.3 reflection { 0, 1 fresnel } } interior { ior 1.6 } }
sphere { < 1.1, 0.7, 1.5>, 0.7 pigment { P } finish { diffuse 0.1 reflection { 0.8 metallic 1 } } }
sphere { < 3.3, 0.7, 1.5>, 0.7 pigment { P } finish { diffuse 0.3 reflection { 0.6 exponent 0.5 } } }
sphere { <-3.3, 0.7, -1>, 0.7 pigment { P } finish { diffuse 0.3 reflection rgb <0.2, 0.5, 0.8> reflection_exponent 2 } }
sphere { <-1.1, 0.7, -1>, 0.7 pigment { rgbf <1, 1, 1, 0.9> } finish { diffuse 0 ambient 0 reflection { 0.1, 0.9 } conserve_energy } }
sphere { < 1.1, 0.7, -1>, 0.7 pigment { P } finish { diffuse 0.2 reflection { 0.2, 1 fresnel on metallic 0.6 } } interior { ior 2 } }
sphere { < 3.3, 0.7, -1>, 0.7 pigment { P } finish { diffuse 0.3 reflection { 0.5 falloff 0.5 } } }
