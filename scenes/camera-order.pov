// camera-order.pov: camera items in an unusual order (translate and look_at
// before location, right after look_at, a final rotate). POV-Ray applies the
// vectors first, then angle, then look_at, then the transformations.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { translate <0.5,0,0> look_at <0,1.2,0> location <0.3,2.2,-6> right x*image_width/image_height angle 55 rotate y*10 }
light_source { <5,8,-6> color rgb 1 }
plane { y, 0 pigment { color rgb <0.8,0.8,0.7> } }
sphere { <0,1,0>, 1 pigment { color rgb <0.9,0.2,0.1> } finish { phong 0.8 } }
box { <-2.5,0,-0.5>, <-1.5,1,0.5> pigment { color rgb <0.2,0.6,0.9> } }
