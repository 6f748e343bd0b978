// cam-mesh-smooth.pov: mesh_camera distribution 3 with smooth: a uv-mapped
// quad of two faces whose vertex normals lean outwards, so the rays fan
// out from the quad like a wide-angle lens (without smooth every ray of
// a face would run along its flat normal).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
#declare Quad = mesh2 {
  vertex_vectors { 4, <-0.4, 0.7, -4>, <0.4, 0.7, -4>, <0.4, 1.3, -4>, <-0.4, 1.3, -4> }
  normal_vectors { 4, <-0.6, -0.45, 1>, <0.6, -0.45, 1>, <0.6, 0.3, 1>, <-0.6, 0.3, 1> }
  uv_vectors { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> }
  face_indices { 2, <0, 2, 1>, <0, 3, 2> }
}
camera { mesh_camera { 1 3 mesh { Quad } smooth } }
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
cylinder { <1.6, 0, 0.5>, <1.6, 2, 0.5>, 0.3 pigment { color rgb <0.3, 0.8, 0.4> } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
