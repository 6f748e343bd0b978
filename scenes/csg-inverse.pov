// csg-inverse.pov: unions under an inversion lose their inner surfaces, as
// in POV-Ray, which turns an inverted union into the intersection of its
// inverted children (and, inverted again, into a merge). Left: a bowl (a
// sphere below y = 0) with a subtracted union of two overlapping spheres;
// the cavity's floor is the union's outer surface only. Middle: the same
// with the union nested in another union. Right, behind: a see-through
// union inverted twice (a merge: no inner walls) beside a plain union
// (inner walls visible).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 6, -7> right x*image_width/image_height look_at <0, -0.3, 0.4> angle 48 }
light_source { <4, 10, -5> color rgb 1 }
light_source { <-5, 6, -6> color rgb 0.35 }
background { color rgb <0.1, 0.11, 0.14> }
plane { y, -1.6 pigment { color rgb 0.6 } }

#declare Shiny = finish { phong 0.5 phong_size 30 }
#declare U = union { sphere { <-0.5, 0, 0>, 0.9 } sphere { <0.5, 0, 0>, 0.9 } }

difference {
  sphere { 0, 1.5 }
  object { U }
  plane { -y, 0 }
  pigment { color rgb <0.9, 0.6, 0.3> } finish { Shiny }
  translate <-1.8, 0, -0.6>
}
difference {
  sphere { 0, 1.5 }
  union { object { U } sphere { <0, 0.5, 0.5>, 0.8 } }
  plane { -y, 0 }
  pigment { color rgb <0.4, 0.8, 0.5> } finish { Shiny }
  translate <1.8, 0, -0.6>
}
object {
  object { U inverse } inverse
  pigment { color rgbt <0.4, 0.6, 1, 0.6> } finish { Shiny }
  scale 0.8 translate <-1.3, -0.4, 2.6>
}
object {
  U
  pigment { color rgbt <1, 0.5, 0.6, 0.6> } finish { Shiny }
  scale 0.8 translate <1.3, -0.4, 2.6>
}
