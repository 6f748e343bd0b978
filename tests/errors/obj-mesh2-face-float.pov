// expect: 5:24: face_indices has more entries than its count (1)
// POV-Ray: "No matching } in face_indices": the float 0 is the face <0,0,0>, so <0,1,2> is one too many.
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 1, 0, <0,1,2> }
}
