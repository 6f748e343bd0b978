// expect: 6:20: normal_indices has 1 entry of the 2 its count says
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 1, <0,0,1> }
  face_indices { 2, <0,1,2>, <2,1,0> }
  normal_indices { 2, <0,0,0> }
}
