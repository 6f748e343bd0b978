// expect: 4:18: the number of faces must be from 0 to 2147483647, found -1
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { -1, <0,1,2> }
}
