// Coloured shadows: light through filtering and transmitting objects.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <-1.2,1,0>, 0.9 pigment { rgbf <1,0.3,0.3,0.8> } finish { Mat } }
box { <0.3,0.3,-0.6>, <1.9,1.6,0.2> pigment { rgbt <0.3,0.5,1,0.6> } finish { Mat } }
sphere { <0.5,0.4,-1.6>, 0.4 pigment { rgb <0.2,1,0.2> filter 0.5 transmit 0.3 } no_shadow }
light_source { <-2,7,-4>, rgb 1 }
