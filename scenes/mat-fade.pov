// mat-fade.pov: attenuation inside interiors: fade_distance and
// fade_power (1, 2 and the exponential >= 1000) with fade_color, in
// slabs of growing thickness and a sphere, against a bright background.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }
camera { location <0, 2, -9> look_at <0, 1, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 9, -6> color rgb 1 }
background { color rgb <0.9, 0.9, 0.85> }
plane { y, 0 pigment { color rgb 0.6 } }
#declare T = texture { pigment { rgbf 1 } finish { ambient 0 diffuse 0 } }
box { <-4, 0.01, -0.2>, <-2.6, 2, 0.2> texture { T } interior { fade_distance 0.5 fade_power 1 } }
box { <-2.4, 0.01, -0.5>, <-1, 2, 0.5> texture { T } interior { fade_distance 0.5 fade_power 2 fade_color <0.8, 0.3, 0.1> } }
box { <-0.8, 0.01, -1>, <0.6, 2, 1> texture { T } interior { fade_distance 1 fade_power 1001 fade_color <0.2, 0.5, 0.9> } }
sphere { <2.3, 1, 0>, 1 texture { T } interior { ior 1.4 fade_distance 0.7 fade_power 2 fade_color <0.1, 0.6, 0.3> } }
