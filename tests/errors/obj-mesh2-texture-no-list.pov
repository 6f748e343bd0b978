// expect: 4:30: a face's texture index needs a texture_list before face_indices
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, <0,1,2>, 0 }
}
