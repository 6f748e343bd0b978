// expect: 3:20: vertex_vectors has 3 entries of the 4 its count says
mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, <0,1,2> }
}
