// expect: 6:39: face_indices has more entries than its count (1)
// POV-Ray: "No matching } in face_indices": after 3 texture indices a float starts the next face.
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 1, <0,1,2>, 0, 1, 0, 1 }
}
