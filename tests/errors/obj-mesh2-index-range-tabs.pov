// expect: 6:4: vertex index 3 is out of range (the list has 3 entries)
mesh2 {
	vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
	face_indices { 3,
		<0,1,2>, <2,1,0>,
			<0, 3, 1>
	}
}
