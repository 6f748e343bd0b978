// scale.pov: scale and translation invariance (run.sh: scale-tiny,
// scale-huge, far-translate). A small scene (two spheres, one of them a
// mirror, a box on a plane, a torus, two lights with hard shadows) whose
// every coordinate -- camera location and look_at, lights, object
// positions and sizes -- goes through P(V) = V*S + T*<1, 0.7, -0.8>, with
// S and T given on the command line (Declare=S=1e-4, Declare=T=1e5).
// Nothing is scaled by a transformation: the coordinates themselves are
// tiny, huge or far from the origin, as in a scene written in other units
// or placed elsewhere (only the torus, which has no centre of its own, is
// moved into place by a translate).
//
// Property: the images for S = 1e-4 and S = 1e4 and for T = 1e5 are the
// image for S = 1, T = 0, up to a handful of pixels: run.sh allows at
// most 4 pixels of 19200 to differ by more than 1/255 (rounding). A
// tolerance that intersects, shadows or reflects at a fixed distance
// (shadow acne, holes, lost shadows) breaks this at once.
//
// lucent: S = 1e-4 and 1e4 are bit-identical to S = 1 (they still are at
// 1e-8 and 1e8); T = 1e5 differs in 3 pixels (one on the edge of a
// shadow, two by 1/255). POV-Ray 3.7 fails S = 1e-4 (about 22% of the pixels
// differ: the torus is cut open and the shadows are lost, its fixed
// epsilons are as large as the scene) and S = 1e4 (160 pixels: the far
// plane vanishes at the horizon, beyond its maximum distance of 1e7); it
// passes T = 1e5 (1 pixel on a box edge).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (S) #declare S = 1; #end
#ifndef (T) #declare T = 0; #end
#declare Off = <1, 0.7, -0.8>*T;
#macro P(V) (V*S + Off) #end

camera {
  location P(<0.4, 2.5, -6.5>)
  right x*image_width/image_height
  look_at P(<0, 0.8, 0>)
  angle 50
}
light_source { P(<-5, 9, -4>) color rgb 1 }
light_source { P(<6, 5, -7>) color rgb 0.3 }
background { color rgb <0.2, 0.3, 0.5> }

plane { y, Off.y pigment { color rgb 0.75 } }
sphere { P(<-1.8, 0.7, 0.5>), 0.7*S pigment { color rgb <0.9, 0.3, 0.2> }
  finish { phong 0.6 phong_size 40 } }
// the mirror: it shows the other objects, the floor and the shadows
sphere { P(<0.3, 1, 1.2>), 1*S pigment { color rgb 0.8 }
  finish { ambient 0 diffuse 0.2 reflection 0.7 } }
box { P(<1.4, 0, -1.2>), P(<2.6, 0.9, -0.2>) pigment { color rgb <0.3, 0.8, 0.3> } }
torus { 0.6*S, 0.2*S rotate x*-60 translate P(<-0.6, 0.7, -1.6>)
  pigment { color rgb <0.9, 0.8, 0.2> } finish { specular 0.5 } }
