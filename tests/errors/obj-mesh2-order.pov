// expect: 5:3: normal_vectors must come before face_indices in mesh2
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, <0,1,2> }
  normal_vectors { 1, <0,0,1> }
}
