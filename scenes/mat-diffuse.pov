// mat-diffuse.pov: the diffuse family of finish terms. Spheres with
// ambient as a colour, emission, diffuse with albedo and brilliance, the
// two-value `diffuse A, B` lit from behind, and filter/transmit pigments
// (which scale ambient, emission and diffuse by 1 - filter - transmit).
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <1, 0.9, 0.8> }
camera { location <0, 3, -10> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <2, 3, 9> color rgb <0.4, 0.4, 0.5> }
background { color rgb <0.1, 0.12, 0.2> }
plane { y, 0 pigment { color rgb 0.5 } finish { ambient 0.1 diffuse 0.7 } }
#declare P = pigment { color rgb <0.8, 0.4, 0.2> }
sphere { <-3.3, 0.7, 1.5>, 0.7 pigment { P } finish { ambient rgb <0.3, 0.1, 0.5> diffuse 0.3 } }
sphere { <-1.1, 0.7, 1.5>, 0.7 pigment { P } finish { ambient 0 emission rgb <0.2, 0.4, 0.1> } }
sphere { < 1.1, 0.7, 1.5>, 0.7 pigment { P } finish { diffuse albedo 0.5 brilliance 3 } }
sphere { < 3.3, 0.7, 1.5>, 0.7 pigment { P } finish { brilliance 0.4 } }
sphere { <-3.3, 0.7, -1>, 0.7 pigment { P } finish { diffuse 0.6, 0.4 } }
sphere { <-1.1, 0.7, -1>, 0.7 pigment { rgbf <0.8, 0.4, 0.2, 0.5> } finish { ambient 0.3 } }
sphere { < 1.1, 0.7, -1>, 0.7 pigment { rgbt <0.2, 0.4, 0.8, 0.6> } finish { emission 0.2 } }
disc { <3.3, 0.9, -1>, <0.3, 0, -1>, 0.8 pigment { P } finish { diffuse 0.5, 0.5 } }
