// expect: 7:5: uv index -1 is out of range (the list has 3 entries)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  uv_vectors { 3, <0,0>, <1,0>, <0,1> }
  face_indices { 2, <0,1,2>, <2,1,0> }
  uv_indices { 2, <0,1,2>,
    <2,1,-1> }
}
