// checks trace() normals of mesh faces whose three normals are equal (within
// 1e-5): POV-Ray shades them flat with the face's own normal, whatever
// direction the normals give; faces whose normals differ stay smooth, and so
// does a lone smooth_triangle with equal normals
#version 3.7;
#macro R6(F) (floor((F)*1000000+0.5)/1000000) #end
#macro V3(V) concat(str(R6(V.x), 0, 6), ",", str(R6(V.y), 0, 6), ",", str(R6(V.z), 0, 6)) #end
#macro T(N, O, X) #local Nr = <0,0,0>; #local P = trace(O, <X+0.2,0.2,-5>, z, Nr); #debug concat(N, " ", V3(P), "  n ", V3(Nr), "\n") #end
#declare M = mesh {
  smooth_triangle { <0,0,0>, <0,0.6,-0.8>, <1,0,0>, <0,0.6,-0.8>, <0,1,0>, <0,0.6,-0.8> }
  smooth_triangle { <2,0,0>, <0,0.6,-0.8>, <3,0,0>, <0,1.2,-1.6>, <2,1,0>, <0,0.6,-0.8> }
  smooth_triangle { <4,0,0>, <0,0.6,-0.8>, <5,0,0>, <0,0.7,-0.8>, <4,1,0>, <0,0.6,-0.8> }
  smooth_triangle { <6,0,0>, <0,0.6,0.8>, <7,0,0>, <0,0.6,0.8>, <6,1,0>, <0,0.6,0.8> }
  smooth_triangle { <8,0,0>, <1e-5,0,-1>, <9,0,0>, <0,0,-1>, <8,1,0>, <0,0,-1> }
  smooth_triangle { <10,0,0>, <1.05e-5,0,-1>, <11,0,0>, <0,0,-1>, <10,1,0>, <0,0,-1> }
  smooth_triangle { <12,0,0>, <1.05e-5*0.7071,1.05e-5*0.7071,-1>, <13,0,0>, <0,0,-1>, <12,1,0>, <0,0,-1> }
  smooth_triangle { <14,0,0>, <0,0,-1>, <15,0,0>, <0.9e-5*0.7071,0.9e-5*0.7071,-1>, <14,1,0>, <-0.9e-5*0.7071,-0.9e-5*0.7071,-1> }
  triangle { <16,0,0>, <16,1,0>, <17,0,0> }
}
T("mesh-equal", M, 0)
T("mesh-equal-scaled", M, 2)
T("mesh-differ", M, 4)
T("mesh-equal-backward", M, 6)
T("mesh-1e-5", M, 8)
T("mesh-1.05e-5", M, 10)
T("mesh-1.05e-5-diagonal", M, 12)
T("mesh-opposite-0.9e-5", M, 14.4)
T("mesh-flat", M, 16)
#declare M2 = mesh2 {
  vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }
  normal_vectors { 2, <0.6,0,-0.8>, <0,0.6,-0.8> }
  face_indices { 2, <0,1,2>, <1,3,2> }
  normal_indices { 2, <0,0,0>, <0,1,1> }
}
T("mesh2-equal", M2, 0)
T("mesh2-differ", M2, 0.7)
T("smooth-triangle-equal", smooth_triangle { <0,0,0>, <0,0.6,-0.8>, <1,0,0>, <0,0.6,-0.8>, <0,1,0>, <0,0.6,-0.8> }, 0)
