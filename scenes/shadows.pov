// shadows.pov: lights and hard shadows. Exercises two coloured point
// lights casting overlapping coloured shadows, a shadowless fill light,
// no_shadow on an object, shadows falling across several objects, a light
// colour given with a float multiplier, and global ambient_light.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.5, 0.5, 0.9> }

camera {
  location <0, 5, -7>
  right x*image_width/image_height
  look_at <0, 0.6, 0>
  angle 50
}

light_source { <-4, 7, -2> color rgb <0.9, 0.4, 0.3> }
light_source { <4, 7, -2> color rgb <0.3, 0.5, 0.9> }
light_source { <0, 3, -8> color rgb 0.2 shadowless }
light_source { <0, 20, 0> color rgb <1, 1, 1>*0.15 }

background { color rgb 0 }

plane { y, 0 pigment { color rgb 0.75 } }

sphere { <0, 0.8, 0>, 0.8 pigment { color rgb 0.9 } }
box { <-2.6, 0, 1>, <-1.6, 1.6, 2> pigment { color rgb <0.9, 0.9, 0.6> } }
box { <1.4, 0, 1.2>, <2.6, 0.5, 2.4> pigment { color rgb <0.6, 0.9, 0.9> } }
// casts no shadow, but receives them
sphere { <1.8, 0.5, -1.5>, 0.5 pigment { color rgb <0.9, 0.5, 0.9> } no_shadow }
// a floating slab shading the ones below
box { <-1.5, 1.9, -1.7>, <-0.6, 2.0, -0.8> pigment { color rgb 0.8 } }
sphere { <-1.05, 0.35, -1.25>, 0.35 pigment { color rgb <0.9, 0.9, 0.9> } }
