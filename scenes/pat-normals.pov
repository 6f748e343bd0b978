// pat-normals.pov: the normal patterns POV-Ray perturbs with formulas of
// their own (bumps, dents, wrinkles; generators 1 and 2, scaled, with bump sizes
// above 1) on flat boxes lit from a low angle, so the perturbation shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 10, -3> look_at <0, 0, 0> angle 40 }
light_source { <-8, 5, -4> color rgb 1 }
#macro B(N, X, Z)
  box { <-1.2, -1, -1.2>, <1.2, 0, 1.2> pigment { rgb <0.9, 0.85, 0.7> } normal { N }
        finish { ambient 0.1 diffuse 0.8 specular 0.4 roughness 0.02 } translate <X, 0, Z> }
#end
B(normal { bumps 0.6 scale 0.3 }, -2.6, 1.3)
B(normal { bumps 2 noise_generator 1 scale 0.5 }, 0, 1.3)
B(normal { dents 1.5 scale 0.4 }, 2.6, 1.3)
B(normal { dents 4 noise_generator 1 scale <0.6, 1, 0.3> }, -2.6, -1.3)
B(normal { bumps 0.8 scale 0.25 rotate 30*y translate 0.3 }, 0, -1.3)
B(normal { wrinkles 0.8 scale 0.3 }, 2.6, -1.3)
