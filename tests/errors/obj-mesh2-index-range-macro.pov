// expect: 6:5: normal index 2 is out of range (the list has 2 entries)
// expect-also: in macro M called from obj-mesh2-index-range-macro.pov:12:1
#macro M()
  normal_indices { 3,
    <0,1,0>, <1,1,1>,
    <1,2,0>
  }
#end
mesh2 {
  vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }
  normal_vectors { 2, <0,0,1>, <0,0,1> } face_indices { 3, <0,1,2>, <2,1,0>, <0,2,1> }
M()
}
