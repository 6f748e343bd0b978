// expect: 6:20: normal_indices has 2 entries but there is only 1 face
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 1, <0,0,1> }
  face_indices { 1, <0,1,2> }
  normal_indices { 2, <0,0,0>, <0,0,0> }
}
