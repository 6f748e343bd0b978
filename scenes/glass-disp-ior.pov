// glass-disp-ior.pov: where POV-Ray 3.7 disperses. Only an interior whose
// ior is written out disperses, even `ior 1` (top row, left to right:
// `ior 1` with dispersion; a declared interior without ior given one; a
// declared `ior 1` given dispersion; an ior in a first interior block and
// dispersion in a second). Without an ior (bottom row: dispersion alone;
// dispersion with a pre-3.1 `finish { ior 1 }`) the dispersion is ignored.
// The last ball shows that a second interior block adds to the first: its
// ior 1.5 still refracts under the fading of the second block.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 2.5, -8> look_at <0, 1.2, 0> angle 44 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
plane { y, 0 pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 5> pigment { checker rgb <0.1, 0.3, 0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
#declare T = texture { pigment { rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.1 } }
#declare I = interior { dispersion 1.3 }
#declare J = interior { ior 1 }
#declare B = sphere { 0, 0.6 }
object { B translate <-2.4, 2, 0> texture { T } interior { ior 1 dispersion 1.3 dispersion_samples 5 } }
object { B translate <-0.8, 2, 0> texture { T } interior { I ior 1 } }
object { B translate <0.8, 2, 0> texture { T } interior { J dispersion 1.3 } }
object { B translate <2.4, 2, 0> texture { T } interior { ior 1 } interior { dispersion 1.3 } }
object { B translate <-1.6, 0.6, 0> texture { T } interior { dispersion 1.3 } }
object { B translate <0, 0.6, 0> texture { T finish { ior 1 } } interior { I } }
object { B translate <1.6, 0.6, 0> texture { T } interior { ior 1.5 } interior { fade_distance 1 fade_power 2 } }
