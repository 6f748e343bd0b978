// expect: 4:16: uv_vectors has 2 entries of the 3 its count says
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  uv_vectors { 3, <0,0>, <1,0> }
  face_indices { 1, <0,1,2> }
}
