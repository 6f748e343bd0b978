// cam-mesh0.pov: mesh_camera distribution 0, two rays a pixel: two meshes
// of 160 x 120 small faces (one per pixel, in image order), each face
// turned towards a common eye point, the second mesh shifted by a
// quarter of a face (POV-Ray's way to anti-alias a mesh camera).
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
#declare W = 160; #declare H = 120; #declare S = 0.025;
#declare Eye = <0, 1, -6>;
#declare Cam = mesh {
#for (J, 0, H - 1) #for (I, 0, W - 1)
  #local C = <(I + 0.5 - W / 2) * S, 1 + (H / 2 - J - 0.5) * S, -3>;
  #local D = vnormalize(C - Eye);
  #local A = vnormalize(vcross(y, D)) * S * 0.3;
  #local B = vnormalize(vcross(D, A)) * S * 0.3;
  triangle { C - A - B, C + B, C + A - B }
#end #end
}
camera { mesh_camera { 2 0 mesh { Cam } mesh { Cam translate <S / 4, -S / 4, 0> } } }
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
