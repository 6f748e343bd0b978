// expect: 6:16: uv_indices has 2 entries but there is only 1 face
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  uv_vectors { 3, <0,0>, <1,0>, <0,1> }
  face_indices { 1, <0,1,2> }
  uv_indices { 2, <0,1,2>, <2,1,0> }
}
