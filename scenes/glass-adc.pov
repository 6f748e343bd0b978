// glass-adc.pov: which rays POV-Ray 3.7 follows under adc_bailout 0.3
// (doc/materials.md, Fidelity notes), from left to right:
//  - two nested balls of filter 0.6 (colour <0.5, 1, 0.2>, then white):
//    a transmitted ray needs the grey of what the surface lets through
//    and its weight (the product of the largest channels) above the
//    bailout, so the inner ball's far side shows nothing;
//  - a mirror box with reflection { 0.1, 0.6 }: weighed by 0.6, whatever
//    it reflects at this angle;
//  - a box with reflection 0.6 metallic 1 and a dark pigment: weighed by
//    0.6 before metallic;
//  - a prism of filter 0.5 and reflection 0.9 with a ball inside, where
//    light is reflected totally: too weak, and then no reflection either;
//  - conserve_energy with fresnel reflection and a tinted filter.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 adc_bailout 0.3 }
camera { location <0, 2.5, -8> look_at <0, 0.9, 0> angle 50 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { y, 0 pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 5> pigment { checker rgb <0.1, 0.3, 0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
sphere { <-3, 1, 0>, 0.9 pigment { rgbf <0.5, 1, 0.2, 0.6> } finish { ambient 0 diffuse 0.1 } interior { ior 1.2 } }
sphere { <-3, 1, 0>, 0.5 pigment { rgbf <1, 1, 1, 0.6> } finish { ambient 0 diffuse 0.1 } interior { ior 1.2 } }
box { -0.6, 0.6 rotate <20, 30, 0> translate <-1.4, 0.9, 0> pigment { rgb 0.2 } finish { ambient 0.1 diffuse 0.3 reflection { 0.1, 0.6 } } }
box { -0.6, 0.6 rotate <20, -30, 0> translate <0, 0.9, 0> pigment { rgb <0.2, 0.3, 0.1> } finish { ambient 0.1 diffuse 0.3 reflection 0.6 metallic 1 } }
union {
  intersection { box { -0.7, 0.7 } plane { <-1, 0, 1>, 0 }
    pigment { rgbf <1, 1, 1, 0.5> } finish { ambient 0 diffuse 0.1 reflection 0.9 } interior { ior 2.2 } }
  sphere { <0.45, 0, 0>, 0.15 pigment { rgb <1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }
  rotate y*-10 translate <1.5, 0.8, -0.5> }
box { -0.65, 0.65 rotate <35, 40, 0> translate <3.2, 1.1, 0>
  pigment { rgbf <0.9, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0 reflection { 0.05, 0.8 fresnel } conserve_energy } interior { ior 2.2 } }
