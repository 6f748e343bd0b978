// shadowless lights: no shadows and no highlights.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <-1,0.8,0>, 0.8 pigment { rgb <1,0.8,0.6> } finish { ambient 0.05 diffuse 0.6 phong 0.8 specular 0.5 } }
sphere { <1.1,0.6,0>, 0.6 pigment { rgb <0.6,0.8,1> } finish { ambient 0.05 diffuse 0.6 phong 0.8 } }
light_source { <-3,5,-4>, rgb 0.8 shadowless }
light_source { <4,3,-3>, rgb 0.5 }
