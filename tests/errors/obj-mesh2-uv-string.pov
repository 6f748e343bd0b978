// expect: 4:19: expected a 2-component uv vector, found a string
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  uv_vectors { 1, "uv" }
  face_indices { 1, <0,1,2> }
}
