// Point lights of two colours: diffuse, phong highlights and hard shadows.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <-1,1,0>, 1 pigment { rgb <1,0.9,0.7> } finish { Mat } }
box { <0.7,0,-0.5>, <1.7,1.5,0.5> rotate y*20 pigment { rgb <0.7,0.8,1> } finish { Mat } }
light_source { <-4,6,-3>, rgb <1,0.9,0.8> }
light_source { <5,3,-2>, rgb <0.3,0.4,0.6> }
