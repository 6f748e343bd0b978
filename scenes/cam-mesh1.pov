// cam-mesh1.pov: mesh_camera distribution 1 with max_distance: the faces
// of two meshes (the image's upper and lower halves, one face per pixel,
// each turned towards a common eye point) summed into one list. Rays
// that meet nothing within 6 units of their face see the background, so
// the far part of the floor is cut off.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
#declare W = 160; #declare H = 120; #declare S = 0.025;
#declare Eye = <0, 1, -6>;
#macro Rows(J0, J1)
mesh {
#for (J, J0, J1) #for (I, 0, W - 1)
  #local C = <(I + 0.5 - W / 2) * S, 1 + (H / 2 - J - 0.5) * S, -3>;
  #local D = vnormalize(C - Eye);
  #local A = vnormalize(vcross(y, D)) * S * 0.3;
  #local B = vnormalize(vcross(D, A)) * S * 0.3;
  triangle { C - A - B, C + B, C + A - B }
#end #end
}
#end
#declare Top = Rows(0, H / 2 - 1)
#declare Bottom = Rows(H / 2, H - 1)
camera { mesh_camera { 1 1 6 mesh { Top } mesh { Bottom } } }
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
