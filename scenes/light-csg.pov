// light_source inside CSG, as POV-Ray 3.7 renders it (measured): the light
// is a global light (even inside a light_group) that moves with the CSG's
// later transformations and is copied with it; a CSG that is only declared
// gives no light. The light is no part of the solid: an intersection
// ignores it, but a difference whose body starts with a light subtracts
// every object in it: the last object below is everything outside both
// the box and the sphere (the box without the sphere, and the sphere's
// part outside the box), not the box minus the sphere.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,5,-8> look_at <0,0.6,0> angle 45 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare Lamp = union {
  sphere { <0,0.5,0>, 0.5 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.8 phong 0.4 } }
  light_source { <0,1.5,-0.5>, rgb <0.5,0.25,0.1> }
}
#declare Unused = union { sphere { <0,-2,0>, 0.1 } light_source { <0,3,0>, rgb <0,0,1> } }
object { Lamp translate x*-2.5 }
object { Lamp translate x*2.5 rotate y*-15 }
light_group {
  union {
    cylinder { <0,0,0>, <0,0.3,0>, 0.6 pigment { rgb 1 } }
    light_source { <-1,2,-1>, rgb <0.1,0.3,0.5> }
    translate <0,0,2>
  }
}
intersection {
  sphere { <-0.3,0.6,0>, 0.6 } sphere { <0.3,0.6,0>, 0.6 }
  light_source { <0,4,-3>, rgb 0.3 }
  pigment { rgb <1,0.9,0.6> }
  translate z*-1.5
}
difference {
  light_source { <3,5,-2>, rgb 0.2 }
  box { <-0.5,0,-0.5>, <0.5,1,0.5> }
  sphere { <-0.5,1,-0.5>, 0.45 }
  pigment { rgb <0.6,1,0.6> }
  translate <1.2,0,1.5>
}
