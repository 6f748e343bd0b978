// Cylinder lights: light along the axis inside the radius, a smooth edge to
// the falloff radius, parallel shadows; tightness softens it.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <0,0.5,0>, 0.5 pigment { rgb 1 } finish { Mat } }
light_source { <-1,6,0>, rgb <1,0.8,0.6> cylinder radius 1.2 falloff 1.8 point_at <0,0,0> }
light_source { <3,3,-1>, rgb <0.5,0.7,1> cylinder radius 0.5 falloff 1.5 tightness 2 point_at <2,0,1> }
