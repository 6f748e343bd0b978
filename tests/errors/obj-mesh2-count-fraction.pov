// expect: 3:43: vertex_vectors has more entries than its count (2)
mesh2 {
  vertex_vectors { 2.5, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, <0,1,2> }
}
