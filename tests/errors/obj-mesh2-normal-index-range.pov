// expect: 6:32: normal index 1 is out of range (the list has 1 entry)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 1, <0,0,1> }
  face_indices { 2, <0,1,2>, <2,1,0> }
  normal_indices { 2, <0,0,0>, <0,1,0> }
}
