// obj-meshes.pov: triangles and meshes. Exercises triangle,
// smooth_triangle (interpolated normals), mesh of smooth triangles with a
// per-triangle texture, declared once and placed three times (one shared
// hierarchy), and mesh2 with vertex_vectors, normal_vectors,
// texture_list, face_indices with texture indices, normal_indices and
// inside_vector.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 4, -9> right x*image_width/image_height look_at <0, 0.8, 0> angle 50 }
light_source { <5, 10, -6> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.3 }
background { color rgb <0.08, 0.09, 0.12> }
plane { y, 0 pigment { color rgb 0.7 } }

#declare Shiny = finish { phong 0.6 phong_size 40 }

triangle { <-4.5, 0, 1>, <-2.5, 0, 1.5>, <-3.6, 2.2, 1.2> pigment { color rgb <0.9, 0.3, 0.2> } finish { Shiny } }
smooth_triangle { <-2, 0, 1>, <-0.6, 0, -1>, <0, 0, 1.5>, <0.6, 0, -1>, <-1, 2, 1.2>, <0, 1, -1>
  pigment { color rgb <0.3, 0.8, 0.3> } finish { Shiny } }

#declare Gold = texture { pigment { color rgb <1, 1, 0.3> } finish { Shiny } }
// A smooth dome of 4 x 8 quads.
#declare Dome = mesh {
  #for (I, 0, 3)
    #for (J, 0, 7)
      #local A0 = J * 45; #local A1 = (J + 1) * 45;
      #local E0 = I * 22.5; #local E1 = (I + 1) * 22.5;
      #local P00 = <cos(radians(E0)) * cos(radians(A0)), sin(radians(E0)), cos(radians(E0)) * sin(radians(A0))>;
      #local P01 = <cos(radians(E0)) * cos(radians(A1)), sin(radians(E0)), cos(radians(E0)) * sin(radians(A1))>;
      #local P10 = <cos(radians(E1)) * cos(radians(A0)), sin(radians(E1)), cos(radians(E1)) * sin(radians(A0))>;
      #local P11 = <cos(radians(E1)) * cos(radians(A1)), sin(radians(E1)), cos(radians(E1)) * sin(radians(A1))>;
      smooth_triangle { P00, P00, P01, P01, P11, P11 }
      smooth_triangle { P00, P00, P11, P11, P10, P10
        #if (J = 2) texture { Gold } #end }
    #end
  #end
  pigment { color rgb <0.2, 0.4, 0.9> } finish { Shiny }
}
object { Dome scale 0.8 translate <1.5, 0, 1.6> }
object { Dome scale 0.5 translate <3.4, 0, 1> }
object { Dome scale <0.6, 1.2, 0.6> rotate z*20 translate <3.6, 0.3, -1.6> }

// A square pyramid: 5 vertices, 6 faces, two textures.
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
  normal_vectors { 5, <-1, 0.5, -1>, <1, 0.5, -1>, <1, 0.5, 1>, <-1, 0.5, 1>, <0, 1, 0> }
  texture_list { 2,
    texture { pigment { color rgb <0.8, 0.4, 0.8> } finish { Shiny } }
    texture { pigment { color rgb <0.2, 0.8, 0.8> } finish { Shiny } } }
  face_indices { 6, <0, 1, 4>, 0, <1, 2, 4>, 1, <2, 3, 4>, 0, <3, 0, 4>, 1, <0, 2, 1>, 0, <0, 3, 2>, 0 }
  normal_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
  inside_vector y
  rotate y*20 translate <-1.6, 0, -1.8>
}
