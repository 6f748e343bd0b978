// expect: 4:18: face_indices has 1 entry of the 2 its count says
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 2, <0,1,2> }
}
