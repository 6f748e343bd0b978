// looks_like: the object is placed at the light, moves with it, and casts
// no shadow; the light is declared and placed twice, transformed.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
sphere { <0,0.6,0.8>, 0.6 pigment { rgb 1 } finish { Mat } }
#declare Lamp = light_source {
  <0,1.8,0>, rgb <1,0.85,0.6>
  looks_like { sphere { 0, 0.25 pigment { rgb <1,1,0.7> } finish { ambient 1 diffuse 0 } } }
}
light_source { Lamp translate <-1.5,0,-0.5> }
light_source { Lamp rotate y*-60 translate <1.6,0.3,0> }
