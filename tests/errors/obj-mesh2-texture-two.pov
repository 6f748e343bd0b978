// expect: 5:21: a face has 1 or 3 texture indices, not 2
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 1, <0,1,2>, 0, 1 }
}
