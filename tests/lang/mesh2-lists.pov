// mesh2-lists.pov: how mesh2's lists are read (the lexer keeps runs of
// literal vectors compactly): commas left out, signs, exponents, a vector
// that is an operand of an expression, vectors from identifiers and
// #for loops, texture indices after faces, normal_indices for the first
// faces only. Each mesh's extent shows which vertices it used.
#declare V = <4, 5, 6>;
#macro Ext(M)
  #debug concat(vstr(3, min_extent(M), ",", 0, 3), " / ", vstr(3, max_extent(M), ",", 0, 3), "\n")
#end
#declare M1 = mesh2 {
  vertex_vectors { 4, <0,0,0> <1,0,0>, <0,1,0> , < -1.5e1 , +2 , .5 > }
  face_indices { 2, <0,1,2> <0,2,3> }
}
Ext(M1)
#declare M2 = mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>*3, V, <0,1,0> - <0,0,1> }
  face_indices { 2, <0,1,2>, <0,2,3> }
}
Ext(M2)
#declare M3 = mesh2 {
  vertex_vectors { 6,
    #for (I, 0, 5)
      <I, I * I, -I>,
    #end
  }
  normal_vectors { 2, <0,1,0>, <1,0,0> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  face_indices { 3, <0,1,2>, 1, <2,3,4>, 0, 1, 0, <3,4,5> }
  normal_indices { 1, <0,1,0> }
}
Ext(M3)
#declare M4 = mesh2 {
  vertex_vectors { 3, <0, 0, 0>, <1, 1, 1>, <2, -2, 0.25> }
  uv_vectors { 3, <0,0> <1,0>, <0.5,1> }
  face_indices { 1, <0, 1, 2> }
  uv_indices { 1, <0, 1, 2> }
}
Ext(M4)
