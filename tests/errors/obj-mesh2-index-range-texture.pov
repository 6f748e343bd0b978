// expect: 8:14: vertex index 7 is out of range (the list has 3 entries)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 5,
    <0,1,2> 0,
    <2,1,0> 1, <1,2,0> 1,
    <0,1,2>, <0,7,1> 0
  }
}
