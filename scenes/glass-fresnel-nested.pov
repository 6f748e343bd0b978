// glass-fresnel-nested.pov: which ior pair fresnel reflection uses where a
// ray leaves glass. POV-Ray 3.7 takes it by its own rule, not by
// refraction's (doc/materials.md, Fidelity notes): a nested sphere reflects
// nothing where the ray leaves it. Left: a lone glass sphere; middle: the
// same sphere inside a larger clear sphere of ior 1.2; right: three spheres
// overlapping in a row (ior 1.5, 2, 2.5). All reflect by fresnel only, so
// the inner reflections show as bright rims and ghost images. The camera is
// outside every object (no plane around it).
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0.3, 1.4, -9> look_at <0.3, 0.8, 0> angle 46 }
light_source { <-4, 8, -6>, rgb 1 }
background { rgb <0.25, 0.3, 0.4> }
box { <-8, -1, -3>, <8, 0, 6> pigment { checker rgb <0.9, 0.2, 0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 5> pigment { checker rgb <0.1, 0.3, 0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
#declare Fres = texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } } }
sphere { <-2.4, 0.9, 0>, 0.8 texture { Fres } interior { ior 1.5 } }
sphere { <0, 0.9, 0>, 0.8 texture { Fres } interior { ior 1.5 } }
sphere { <0, 0.9, 0>, 1.05 texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 } } interior { ior 1.2 } }
sphere { <2.0, 0.9, 0>, 0.5 texture { Fres } interior { ior 1.5 } }
sphere { <2.5, 0.9, 0>, 0.5 texture { Fres } interior { ior 2 } }
sphere { <3.0, 0.9, 0>, 0.5 texture { Fres } interior { ior 2.5 } }
