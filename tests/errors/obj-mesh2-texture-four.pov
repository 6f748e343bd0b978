// expect: 5:39: a face has at most 3 texture indices
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 1, <0,1,2>, 0, 1, 0, 1 }
}
