// glass-tir.pov: total internal reflection. Where the light transmitted
// through a surface reflects totally, POV-Ray 3.7 traces the mirrored ray
// alone and adds it whole: not filtered by the pigment, and not joined by
// the finish's reflection (doc/materials.md, Fidelity notes). Three dense
// tilted cubes (ior 2.2) show it: one filtering half its light with
// constant reflection 0.3, one with fresnel reflection and
// conserve_energy, one transmitting (rgbt) with a tinted pigment.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 2.5, -8> look_at <0, 0.9, 0> angle 44 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { y, 0 pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 5> pigment { checker rgb <0.1, 0.3, 0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
#declare Cube = box { -0.65, 0.65 rotate <35, 40, 0> translate y*1.1 }
object { Cube translate -2.2*x
  pigment { rgbf <1, 1, 1, 0.5> } finish { ambient 0.1 diffuse 0.2 reflection 0.3 } interior { ior 2.2 } }
object { Cube
  pigment { rgbf <0.9, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0 reflection { 0.05, 0.8 fresnel } conserve_energy } interior { ior 2.2 } }
object { Cube translate 2.2*x
  pigment { rgbt <1, 0.6, 0.3, 0.7> } finish { ambient 0.1 diffuse 0.2 reflection { 0.1 exponent 0.5 } } interior { ior 2.2 } }
