// light_group: the group's light lights only its objects; the global light
// lights them only with global_lights; a nested group also gets the lights
// of the group around it; transformations move the group's lights.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
#declare Floor = plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Mat = finish { ambient 0.05 diffuse 0.8 phong 0.4 }
object { Floor }
light_group {
  sphere { <-1.4,0.7,0>, 0.7 pigment { rgb 1 } finish { Mat } }
  light_source { <-4,2,-1>, rgb <1,0.2,0.1> }
}
light_group {
  light_group {
    box { <-0.5,0.01,-0.5>, <0.5,1,0.5> pigment { rgb 1 } finish { Mat } }
    light_source { <0,2,-3>, rgb <0.1,0.3,1> }
    global_lights on
    translate x*1.5
  }
  sphere { <0.3,0.4,-1>, 0.4 pigment { rgb 1 } finish { Mat } }
  light_source { <4,3,0>, rgb <0.2,0.8,0.2> }
}
light_source { <1,6,-3>, rgb 0.6 }
