// mat-irid.pov: iridescence (irid with amount and thickness) at several
// film thicknesses, seen and lit at many angles on spheres and a plane.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -10> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-5, 9, -7> color rgb 1 }
background { color rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { color rgb 0.5 } finish { irid { 0.3 thickness 0.1 } } }
#declare P = pigment { color rgb <0.5, 0.5, 0.55> }
sphere { <-3.3, 0.9, 0>, 0.9 pigment { P } finish { irid { 0.35 thickness 0.05 } } }
sphere { <-1.1, 0.9, 0>, 0.9 pigment { P } finish { irid { 0.35 thickness 0.3 } phong 0.5 } }
sphere { < 1.1, 0.9, 0>, 0.9 pigment { P } finish { irid { 0.6 thickness 0.8 } diffuse 0.4 } }
sphere { < 3.3, 0.9, 0>, 0.9 pigment { P } finish { irid { 1 thickness 2 } diffuse 0.3 } }
