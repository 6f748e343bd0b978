// expect: 9:14: vertex index 3 is out of range (the list has 3 entries)
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  face_indices { 4, <0,1,2>
    /* the second face,
       then the third */
    <2, 1, 0>
    // the bad one:
    <1,2,0>, <1,3,0>
  }
}
