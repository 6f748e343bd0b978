// projected_through: light reaches only where its ray crosses the object;
// objects between the light and it cast no shadow.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
#declare Slot = box { <-1.2,2.9,-0.3>, <1.2,3.1,0.3> }
sphere { <0.3,0.5,0>, 0.5 pigment { rgb 1 } finish { Mat } }
box { <-1,4,-1>, <1,4.2,1> pigment { rgb 1 } no_image }
light_source { <0,5,0>, rgb 1 projected_through { Slot } }
light_source { <-3,3,-4>, rgb 0.3 spotlight radius 10 falloff 15 point_at <-0.5,0,1.5> projected_through { sphere { <-2.25,2.25,-2.75>, 0.2 } } }
light_source { <0,10,-10>, rgb 0.15 }
