// expect: 3:26: 2000000000 vertices is more than a mesh may have (100000000; lucent --limit mesh-size=N raises it)
// The mesh size limit: a mesh2 count is checked before its list is read.
mesh2 { vertex_vectors { 2000000000, <0,0,0> } face_indices { 1, <0,0,0> } }
