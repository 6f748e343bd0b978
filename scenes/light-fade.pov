// Light fading: 2 / (1 + (d / fade_distance)^fade_power), linear and
// quadratic; a fade_power without fade_distance does nothing.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <0,0.7,0.5>, 0.7 pigment { rgb 1 } finish { Mat } }
light_source { <-2,1.5,-1>, rgb <1,0.7,0.4> fade_distance 1.5 fade_power 2 }
light_source { <2.5,1,0>, rgb <0.4,0.6,1> fade_distance 3 fade_power 1 }
light_source { <0,8,-8>, rgb 0.2 fade_power 2 }
