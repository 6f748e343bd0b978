// mesh2.pov: a square pyramid as mesh2: five vertices with normals
// (smooth shading), a list of two textures, and six faces that index
// them. The faces without a texture index (the two at the back and the
// base) take the mesh's own texture.
#version 3.7;
#include "stage.inc"

mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
  normal_vectors { 5, <-1, 0.5, -1>, <1, 0.5, -1>, <1, 0.5, 1>, <-1, 0.5, 1>, <0, 1, 0> }
  texture_list { 2, texture { T_Violet } texture { T_Cyan } }
  face_indices { 6,
    <0, 1, 4>, 0,  <1, 2, 4>, 1,  <2, 3, 4>,  <3, 0, 4>,
    <0, 2, 1>,  <0, 3, 2> }
  normal_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
  inside_vector y
  texture { T_Gold }
  rotate y*30
}
