// A declared light_group placed twice with object { }: each placement
// gets its own copy of the group's light, which the placement's
// transformations move (POV-Ray 3.7 does the same); the floor, outside
// the group, is lit only by the global light. A union around an inline
// group moves that group's light too.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,4,-7> look_at <0,0.6,0> angle 45 }
plane { y, 0 pigment { rgb 0.9 } finish { ambient 0.05 diffuse 0.9 } }
#declare G = light_group {
  sphere { <0,0.7,0>, 0.7 pigment { rgb 1 } finish { ambient 0.05 diffuse 0.8 phong 0.4 } }
  light_source { <-2,2,-2>, rgb <1,0.3,0.1> }
}
object { G translate x*-1.8 }
object { G translate x*1.8 rotate y*20 }
union {
  light_group {
    box { <-0.4,0,-0.4>, <0.4,0.8,0.4> pigment { rgb 1 } finish { ambient 0.05 diffuse 0.8 } }
    light_source { <-2,1,-1>, rgb <0.2,0.5,1> }
  }
  rotate y*90
  translate z*2
}
light_source { <1,6,-3>, rgb 0.3 }
