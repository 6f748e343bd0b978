// expect: 2:1: a mesh2 needs vertex_vectors and face_indices
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
}
