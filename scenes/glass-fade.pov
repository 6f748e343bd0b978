// glass-fade.pov: where interior fading applies. POV-Ray 3.7 fades light
// only where it leaves a fading interior, by the length of the ray that
// reached that surface (doc/materials.md, Fidelity notes): reflections
// inside the glass, opaque objects seen inside it and the glass's own
// surface colour are not faded. Left: a reflective sphere with fade_power
// 2; middle: a slab with an opaque ball and a clear ball inside it;
// right: exponential fading (fade_power 1001) with fresnel reflection.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 2.2, -8> look_at <0, 0.9, 0> angle 44 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { y, 0 pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 5> pigment { checker rgb <0.1, 0.3, 0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
sphere { <-2.3, 1, 0>, 1
  pigment { rgbf 1 } finish { ambient 0.05 diffuse 0 reflection 0.3 }
  interior { ior 1.5 fade_distance 1 fade_power 2 fade_color <0.5, 0.8, 0.3> } }
box { <-0.8, 0.01, -0.5>, <0.8, 2, 1.5>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.3 fade_distance 0.8 fade_power 2 fade_color <0.2, 0.5, 0.9> } }
sphere { <-0.35, 1.3, 0.5>, 0.3 pigment { rgb <1, 0.9, 0.2> } finish { ambient 0.3 diffuse 0.7 } }
sphere { <0.35, 0.7, 0.5>, 0.3 pigment { rgbf 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
sphere { <2.3, 1, 0>, 1
  pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection { 0.05, 0.6 fresnel } conserve_energy }
  interior { ior 1.5 fade_distance 1.5 fade_power 1001 fade_color <0.9, 0.4, 0.3> } }
