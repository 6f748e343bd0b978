// expect: 4:30: face_indices has more entries than its count (1)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, <0,1,2>, <2,1,0> }
}
