// quality-trace-level.pov: max_trace_level and adc_bailout as POV-Ray 3.7
// applies them. A glass sphere (each refraction takes a trace level), a
// stack of clear panes without refraction (a ray passing straight through
// keeps its level: all eight faces show at max_trace_level 2), a tinted
// see-through box whose reflection weight equals adc_bailout
// (traced: POV-Ray traces a ray whose weight is not below the bailout).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 2 adc_bailout 0.2 }
camera { location <0, 1.5, -4> look_at <0, 0.6, 0> angle 50 right x*image_width/image_height }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.2, 0.3, 0.6> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.1 } }
sphere { <-0.9, 0.7, 0>, 0.6 pigment { color rgbf <0.9, 1, 0.9, 0.9> } finish { reflection 0.3 phong 0.5 } interior { ior 1.5 } }
box { <0.2, 0.01, -0.5>, <1.4, 1.2, 0.5> pigment { color rgbt <1, 0.8, 0.8, 0.7> } finish { reflection 0.2 } }
#declare I = 0;
#while (I < 4)
  box { <-0.3, 1.3, I * 0.2>, <0.3, 1.9, I * 0.2 + 0.02> pigment { color rgbt <0.2, 0.6, 1, 0.75> }
    finish { ambient 0.3 diffuse 0.3 } }
  #declare I = I + 1;
#end
