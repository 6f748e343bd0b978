// mat-glass.pov: refraction. A glass sphere (ior 1.5, Fresnel reflection
// with conserve_energy) over a floor of alternating boxes, a filtered
// (coloured) glass box, a transmitting sphere without refraction, and
// their transparent shadows with fake caustics.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 3.5, -9> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 9, -6> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
#declare I = 0;
#while (I < 10)
  box { <-10 + 2*I, -1, -6>, <-9 + 2*I, 0, 10> pigment { color rgb <0.9, 0.85, 0.7> } }
  box { <-9 + 2*I, -1, -6>, <-8 + 2*I, 0, 10> pigment { color rgb <0.15, 0.2, 0.35> } }
  #declare I = I + 1;
#end
sphere { <-1.6, 1.1, 0>, 1.1
  pigment { rgbf <1, 1, 1, 0.95> }
  finish { ambient 0 diffuse 0 phong 0.8 phong_size 120 reflection { 0, 1 fresnel } conserve_energy }
  interior { ior 1.5 caustics 0.6 } }
box { <0.6, 0.01, -0.6>, <2.2, 1.6, 0.6> rotate y*30
  pigment { rgbf <0.4, 0.9, 0.5, 0.8> }
  finish { ambient 0 diffuse 0.1 reflection 0.05 }
  interior { ior 1.33 } }
sphere { <3.3, 0.6, -1.6>, 0.6 pigment { rgbt <1, 0.3, 0.3, 0.7> } finish { phong 0.5 } }
