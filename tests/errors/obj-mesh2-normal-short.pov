// expect: 4:20: normal_vectors has 2 entries of the 3 its count says
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 3, <0,0,1>, <0,0,1> }
  face_indices { 1, <0,1,2> }
  normal_indices { 1, <0,1,1> }
}
