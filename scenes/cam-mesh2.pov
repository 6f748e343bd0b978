// cam-mesh2.pov: mesh_camera distribution 2, a stereo pair: two meshes
// of 80 x 120 faces, one per eye 0.3 apart, side by side in the image
// (the left mesh in the left half). POV-Ray indexes the right mesh's
// faces by the image's column, not the half's (80 * row + column), so
// the right half starts 80 faces in: one row lower than the left half.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.2, 0.4> }
#declare W = 80; #declare H = 120; #declare S = 0.025;
#macro Eye(E)
mesh {
#for (J, 0, H - 1) #for (I, 0, W - 1)
  #local C = E + <(I + 0.5 - W / 2) * S, (H / 2 - J - 0.5) * S, 3>;
  #local D = vnormalize(C - E);
  #local A = vnormalize(vcross(y, D)) * S * 0.3;
  #local B = vnormalize(vcross(D, A)) * S * 0.3;
  triangle { C - A - B, C + B, C + A - B }
#end #end
}
#end
#declare Left = Eye(<-0.15, 1, -6>)
#declare Right = Eye(<0.15, 1, -6>)
camera { mesh_camera { 1 2 mesh { Left } mesh { Right } } }
sphere { <0, 1, 2>, 1 pigment { checker color rgb <1, 0.3, 0.1> color rgb <1, 0.9, 0.4> scale 0.25 } }
cylinder { <1.6, 0, 0.5>, <1.6, 2, 0.5>, 0.3 pigment { color rgb <0.3, 0.8, 0.4> } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.2 } }
light_source { <-10, 20, -10> color rgb 1 }
