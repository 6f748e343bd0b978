// A parallel light: every ray runs along location -> point_at; the box
// above the light's plane is lit but casts no shadow.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <-1,0.8,0>, 0.8 pigment { rgb 1 } finish { Mat } }
box { <0.5,2.6,-0.3>, <1.5,2.8,0.7> pigment { rgb <1,0.6,0.6> } finish { Mat } }
light_source { <0,2.5,0>, rgb 1 parallel point_at <0.8,0,0.5> }
light_source { <0,10,-10>, rgb 0.2 shadowless }
