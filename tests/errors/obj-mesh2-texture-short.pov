// expect: 4:18: texture_list has 1 entry of the 2 its count says
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } }
  face_indices { 1, <0,1,2>, 0 }
}
