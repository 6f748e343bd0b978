// normal-backlight.pov: lights behind a surface that its perturbed normal
// faces. A bumpy plane lit from just below its horizon (shadows on) and by a
// shadowless light, and a bumpy ball: POV-Ray decides whether a light is in
// front by the perturbed normal, so the bumps facing the light are lit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -4> look_at <0, 0, 0> right x*4/3 }
light_source { <100, -5, 0> color rgb 1 }
light_source { <-30, -2, 10> color rgb <0.3, 0.5, 1> shadowless }
plane { y, 0 pigment { color rgb 0.8 } finish { ambient 0.05 diffuse 0.8 phong 0.5 }
  normal { bumps 1 scale 0.2 } }
sphere { <0, 0.5, 0>, 0.5 pigment { color rgb <1, 0.6, 0.3> } finish { ambient 0.05 } normal { bumps 0.8 scale 0.1 } }
