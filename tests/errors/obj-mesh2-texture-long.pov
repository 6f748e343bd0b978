// expect: 4:51: texture_list has more entries than its count (1)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 1, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 1, <0,1,2>, 0 }
}
