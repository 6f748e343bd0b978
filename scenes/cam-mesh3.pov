// cam-mesh3.pov: mesh_camera distribution 3: the image is the uv square of
// a mesh2 quad (two faces), each pixel's ray starting at the point of the
// quad with that uv and going along the face normal (-z here), moved
// 0.5 along it by location's z.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
#declare Quad = mesh2 {
  vertex_vectors { 4, <-2, -0.5, 0>, <2, -0.5, 0>, <2, 2.5, 0>, <-2, 2.5, 0> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
}
camera { mesh_camera { 1 3 mesh { Quad rotate 180 * y translate 3 * z } } location <0, 0, 0.5> }
sphere { <0, 1, 6>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
