// expect: 7:13: texture index 2 is out of range (the list has 2 entries)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 3,
    <0,1,2> 0,
    <2,1,0> 2,
    <0,2,1> 1
  }
}
