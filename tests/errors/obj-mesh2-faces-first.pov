// expect: 3:3: face_indices needs vertices before it (vertex_vectors is missing or empty)
mesh2 {
  face_indices { 1, <0,1,2> }
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
}
