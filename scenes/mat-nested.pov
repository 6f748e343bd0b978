// mat-nested.pov: nested interiors and total internal reflection. Air
// bubbles (ior 1) inside a glass sphere, a glass sphere inside water (a
// box of ior 1.33), and a dense prism where the rays reflect totally.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -9> look_at <0, 1, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 9, -6> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
#declare I = 0;
#while (I < 10)
  box { <-10 + 2*I, -1, -6>, <-9 + 2*I, 0, 10> pigment { color rgb <0.9, 0.85, 0.7> } }
  box { <-9 + 2*I, -1, -6>, <-8 + 2*I, 0, 10> pigment { color rgb <0.15, 0.2, 0.35> } }
  #declare I = I + 1;
#end
#declare GlassT = texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 } }
sphere { <-2.6, 1.2, 0>, 1.2 texture { GlassT } interior { ior 1.5 } }
sphere { <-2.6, 1.4, -0.6>, 0.4 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.0 } }
box { <-0.8, 0.01, -1>, <1.2, 2, 1> pigment { rgbf <0.7, 0.9, 1, 0.9> } finish { ambient 0 diffuse 0 } interior { ior 1.33 } }
sphere { <0.2, 1, 0>, 0.7 texture { GlassT } interior { ior 1.5 } }
box { <-0.6, -0.6, -0.6>, <0.6, 0.6, 0.6> rotate <30, 40, 10> translate <2.9, 1.1, 0>
  pigment { rgbf <1, 0.95, 0.9, 1> } finish { ambient 0 diffuse 0 } interior { ior 2.4 } }
