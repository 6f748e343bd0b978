// expect: 4:32: normal_vectors has more entries than its count (1)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 1, <0,0,1>, <0,0,1> }
  face_indices { 1, <0,1,2> }
}
