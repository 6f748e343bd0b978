// expect: 4:21: expected a texture or '}', found 'pigment'
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 1, pigment { rgb 1 } }
  face_indices { 1, <0,1,2> }
}
