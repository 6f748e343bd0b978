// degenerate.pov: zero-size and degenerate objects (run.sh: degenerate,
// degenerate-flat). A plain scene (plane, sphere, box, one light with
// shadows) to which Declare=DEGEN=1 adds objects of zero size, in front
// of the camera, on the light's path and on the box's surface:
//   a sphere of radius 0; boxes that are a segment and a point; triangles
//   with two equal corners, three equal corners and three collinear
//   corners, a smooth_triangle with collinear corners, a mesh of a
//   degenerate triangle (and one real triangle hidden under the plane:
//   POV-Ray refuses a mesh with no triangle); a cylinder of radius 0; a
//   cone with both radii 0; a disc of radius 0; a torus { 0, 0 }; an
//   intersection and a merge of zero-size objects; and the box replaced by
//   a difference of it and a sphere of radius 0, a cylinder of radius 0
//   and a zero-thickness box, all centred on its front face.
// Property (1): lucent renders it without error and the image is the one
// without them (DEGEN=0), up to 4 pixels over 1/255.
//
// A box of zero thickness is not zero-size in POV-Ray: it shows as a flat
// rectangle (POV-Ray 3.7 draws it, two-sided, and it casts a shadow), and
// lucent does the same. Declare=FLAT=1 adds two such boxes (one seen face
// on, one lying flat); FLAT=2 gives them a thickness of 1e-7 instead.
// Property (2): the FLAT=1 image equals the FLAT=2 image (a flat box is
// the limit of thin ones), up to 4 pixels over 1/255.
//
// lucent passes both. POV-Ray 3.7 passes (2) and FAILS (1) (1142 pixels
// differ): it warns about the degenerate triangles and drops them, and
// the free-standing zero-size objects vanish, but the difference is
// wrong. Tried one at a time: the radius-0 cylinder removes most of the
// box (1142 pixels: only two slivers of its sides are left), the flat
// box subtracted on the front face leaves a black square on it (106
// pixels), the radius-0 sphere does nothing. Subtracting a set of zero
// volume must leave the solid as it was.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (DEGEN) #declare DEGEN = 0; #end
#ifndef (FLAT) #declare FLAT = 0; #end

camera {
  location <0, 3, -7>
  right x*image_width/image_height
  look_at <0, 0.8, 0>
  angle 55
}
light_source { <-5, 9, -6> color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }

plane { y, 0 pigment { color rgb 0.8 } }
sphere { <1.5, 1, 1>, 1 pigment { color rgb <0.9, 0.4, 0.3> } }
#declare Green = box { <-2.5, 0, 0>, <-1, 1.5, 1.5> pigment { color rgb <0.3, 0.8, 0.4> } }
#declare P = pigment { color rgb <1, 0, 1> }

#if (DEGEN)
  difference {
    object { Green }
    sphere { <-1.75, 0.75, 0>, 0 }
    cylinder { <-2.5, 1.5, 0>, <-1, 1.5, 0>, 0 }
    box { <-2, 0.5, 0>, <-1.5, 1, 0> }
  }
  sphere { <0, 1, -1>, 0 pigment { P } }
  box { <-0.5, 1, -1>, <0.5, 1, -1> pigment { P } }
  box { <0.5, 0.5, -1>, <0.5, 0.5, -1> pigment { P } }
  triangle { <-1, 0.5, -2>, <-1, 0.5, -2>, <1, 1.5, -2> pigment { P } }
  triangle { <-1, 0.5, -2>, <0, 1, -2>, <1, 1.5, -2> pigment { P } }
  triangle { <0, 1, -2>, <0, 1, -2>, <0, 1, -2> pigment { P } }
  smooth_triangle { <-1, 0.5, -2>, y, <0, 1, -2>, y, <1, 1.5, -2>, y pigment { P } }
  mesh {
    triangle { <-1, 0.5, -2>, <0, 1, -2>, <1, 1.5, -2> }
    triangle { <0, -10, 0>, <1, -10, 0>, <0, -10, 1> }
    pigment { P }
  }
  cylinder { <-1, 1, -1.5>, <1, 1, -1.5>, 0 pigment { P } }
  cone { <-1, 0.3, -1.5>, 0, <1, 0.3, -1.5>, 0 pigment { P } }
  disc { <0, 1.5, -1>, -z, 0 pigment { P } }
  torus { 0, 0 translate <0, 1, -1> pigment { P } }
  intersection { sphere { <0, 1, -1>, 0 } box { -1, 1 } pigment { P } }
  merge { sphere { <0, 1, -1>, 0 } cylinder { <-1, 1, -1>, <1, 1, -1>, 0 } pigment { P } }
#else
  object { Green }
#end

#switch (FLAT)
  #case (1) #declare E = 0; #break
  #case (2) #declare E = 1e-7; #break
#end
#if (FLAT)
  box { <-0.5, 0.2, -2>, <0.5, 1.2, -2 + E> pigment { P } }
  box { <0, 0.5, -2.5>, <1.2, 0.5 + E, -1.5> pigment { P } }
#end
