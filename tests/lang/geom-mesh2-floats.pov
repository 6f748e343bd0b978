// mesh2 lists accept a float where a vector goes and read it as the vector of three copies
// (vertex_vectors, normal_vectors, face_indices, normal_indices, uv_indices; uv_vectors as <f,f>).
// In face_indices a float after a face's vector is a texture index, and after its third texture
// index the next face. (normal_indices { 1, 1 } gives a face whose three normals are the same, which
// POV-Ray then shades flat, as any mesh triangle with three equal normals; lucent does not yet.)
#version 3.7;
#macro P(N, O) #debug concat(N, " ", vstr(3, min_extent(O), ",", 0, 6), "  ", vstr(3, max_extent(O), ",", 0, 6), "\n") #end
#macro T(N, O, P0)
  #local Nr = <0,0,0>;
  #local H = trace(O, P0, z, Nr);
  #debug concat(N, " hit ", vstr(3, H, ",", 0, 6), " n ", vstr(3, Nr, ",", 0, 6), "\n")
#end
P("vv", mesh2 { vertex_vectors { 3, 0, 1, <0,2,0> } face_indices { 1, <0,1,2> } })
P("vv-neg", mesh2 { vertex_vectors { 3, -1, 1, <0,2,0> } face_indices { 1, <0,1,2> } })
P("vv-expr", mesh2 { vertex_vectors { 3, <0,0,0>, 2*0.5, <0,2,0> } face_indices { 1, <0,1,2> } })
#declare Q = mesh2 { vertex_vectors { 3, 0, 1, <0,2,0> } face_indices { 1, <0,1,2> } }
T("vv-hit", Q, <0.2,0.5,-5>)
#declare M = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 3, 1, -1, <0,0,-1> } face_indices { 1, <0,1,2> } }
T("nv0", M, <0.01,0.01,-5>)
T("nv1", M, <0.98,0.01,-5>)
T("nv2", M, <0.01,0.98,-5>)
T("nvc", M, <0.3,0.3,-5>)
P("face-float", mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <5,5,5> } face_indices { 2, 3, <0,1,2> } })
P("face-float-trunc", mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <5,5,5> } face_indices { 1, 3.7 } })
P("face-float-tex", mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <5,5,5> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } face_indices { 2, 3, <0,1,2> } })
P("face-after-3tex", mesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <5,5,5> }
  texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } face_indices { 2, <0,1,2>, 1, 1, 1, 3 } })
#declare NI = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } normal_vectors { 2, <0,0,-1>, <1,0,-1> }
  face_indices { 1, <0,1,2> } normal_indices { 1, 1 } }
P("ni-float", NI)
#declare UI = mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } uv_vectors { 2, 0, 0.5 }
  face_indices { 1, <0,1,2> } uv_indices { 1, 1 } }
P("uv-float", UI)
