// Spotlights: POV-Ray's defaults (radius 30, falloff 45), a tight one with
// tightness, and one whose falloff is below its radius (a hard edge).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <0,0.6,0.5>, 0.6 pigment { rgb 1 } finish { Mat } }
light_source { <-2,5,-1>, rgb <1,0.8,0.6> spotlight point_at <-1.5,0,0> }
light_source { <2,4,-2>, rgb <0.5,0.7,1> spotlight radius 8 falloff 20 tightness 10 point_at <1.5,0,0.5> }
light_source { <0,6,2>, rgb <0.6,1,0.6> spotlight radius 12 falloff 5 point_at <0,0,2.5> }
