// obj-blob.pov: blobs: the manual's three spheres with a texture each
// (blended by their fields), cylinders with a negative sphere, ellipsoidal
// (scaled and rotated) components with sturm, and a blob cut by a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> right x*image_width/image_height look_at <0, 1, 0> angle 50 }
light_source { <5, 12, -7> color rgb 1 }
light_source { <-7, 6, -4> color rgb 0.35 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }
#declare Shiny = finish { phong 0.5 phong_size 30 }
blob {
  threshold 0.45
  sphere { <.75, 0, 0>, 1, 1 pigment { color rgb <0.9, 0.2, 0.2> } }
  sphere { <-.375, .64952, 0>, 1, 1 pigment { color rgb <0.2, 0.8, 0.2> } }
  sphere { <-.375, -.64952, 0>, 1, 1 }
  pigment { color rgb <0.2, 0.3, 0.9> } finish { Shiny }
  rotate x*-70 translate <-2.8, 0.9, 1.5>
}
blob {
  threshold 0.5
  cylinder { <-1, 0, 0>, <1, 0, 0>, 0.6, 1 }
  cylinder { <0, 0, -1>, <0, 1.6, 0.5>, 0.5, strength 1.2 }
  sphere { <0.3, 0.4, -0.3>, 0.6, -1.5 }
  pigment { color rgb <0.9, 0.7, 0.2> } finish { Shiny }
  translate <0.2, 0.6, 2.2>
}
blob {
  threshold 0.4
  sphere { 0, 1, 1 scale <1.4, 0.5, 0.8> rotate z*30 }
  sphere { 0, 1, 1 scale <0.5, 1.3, 0.5> rotate x*-25 translate <0.5, 0.4, 0> pigment { color rgb <0.9, 0.9, 0.9> } }
  component 0.8, 0.7, <-0.8, 0.3, 0>
  sturm
  pigment { color rgb <0.5, 0.2, 0.7> } finish { Shiny }
  translate <2.6, 1, 0.8>
}
intersection {
  blob {
    threshold 0.5
    sphere { <-0.4, 0, 0>, 1, 1 } sphere { <0.4, 0, 0>, 1, 1 } sphere { <0, 0.6, 0>, 0.8, 1 }
  }
  box { <-2, -2, -2>, <2, 2, -0.1> inverse }
  pigment { color rgb <0.3, 0.8, 0.8> } finish { Shiny }
  rotate y*-30 translate <0, 0.5, -1.4>
}
