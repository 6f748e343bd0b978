// A circular area light, and a linear one (a row of lights).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
#declare Things = union {
  sphere { <-1.2,0.8,0>, 0.8 pigment { rgb <1,0.9,0.7> } finish { Mat } }
  box { <0.5,0.01,-0.4>, <1.5,1.6,0.4> rotate y*25 pigment { rgb <0.7,0.8,1> } finish { Mat } }
  cylinder { <0,0.01,1.5>, <0,2.2,1.5>, 0.15 pigment { rgb 1 } finish { Mat } }
}
object { Floor } object { Things }
light_source { <-1,5,-2>, rgb 0.7 area_light <3,0,0>, <0,0,3>, 6, 6 circular }
light_source { <3,4,-1>, rgb <0.3,0.35,0.5> area_light <0,0,3>, <0,1,0>, 8, 1 }
