// coincident.pov: nearly and exactly coincident surfaces (run.sh:
// coincident, coincident-dark). Four arrangements, in one colour each so
// that which of two coincident faces is hit cannot show:
//   - two boxes side by side, 1e-6 apart (G), a light grazing their tops
//     from each side so that shadow rays from one top skim the other;
//   - two boxes stacked 1e-6 apart, inside a merge (whose inside tests
//     decide which faces are kept);
//   - a box lying on the plane: its bottom face is the plane (POV-Ray's
//     issue 125, black speckles on the plane and the box);
//   - a box sunk flush into the plane, its top face in the plane, in the
//     plane's colour.
// With Declare=REF=1 the same scene is built without any coincidence:
// each pair is one box, the boxes reach 1 unit below the plane and the
// flush box is left out. The visible surfaces are the same, so the
// images must be too.
//
// Properties: (1) the image equals the REF image up to 4 pixels over
// 1/255; (2) no pixel is darker than in the REF image by more than 0.1
// (a black speckle: a shadow ray that finds the neighbouring surface, or
// a ray that hits the wrong side).
//
// lucent passes both, bit-identical to REF. POV-Ray 3.7 passes too
// (bit-identical): the speckles of issue 125 did not show. An earlier
// form of this scene (without the flush box and the grazing light) was
// also tried with G = 0 and G = -1e-6, scaled by 100 and 1e4, moved 1e5
// away, with the boxes in a union or a merge: both renderers kept
// passing (POV-Ray 1 pixel off at most).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (REF) #declare REF = 0; #end
#declare G = 1e-6;

camera {
  location <0, 5, -9>
  right x*image_width/image_height
  look_at <0, 0.4, 0>
  angle 60
}
light_source { <12, 6, -5> color rgb 1 }
// grazing the tops of the side-by-side pair, from the left
light_source { <-14, 1.05, -3> color rgb 0.5 }
background { color rgb <0.1, 0.2, 0.5> }

#declare F = finish { ambient 0.1 diffuse 0.9 }
#declare Floor = pigment { color rgb <0.9, 0.8, 0.6> }
#declare A = pigment { color rgb <0.6, 0.8, 1> }
#declare B = pigment { color rgb <1, 0.6, 0.6> }

plane { y, 0 pigment { Floor } finish { F } }
#if (REF)
  box { <-4, -1, -1>, <-0.5, 1, 1> pigment { A } finish { F } }
  box { <0.5, -1, -1>, <4, 1.2, 1> pigment { B } finish { F } }
  box { <-2, -1, -3.5>, <2, 0.5, -2> pigment { A } finish { F } }
#else
  box { <-4, 0, -1>, <-1.75, 1, 1> pigment { A } finish { F } }
  box { <-1.75 + G, 0, -1>, <-0.5, 1, 1> pigment { A } finish { F } }
  merge {
    box { <0.5, 0, -1>, <4, 0.6, 1> }
    box { <0.5, 0.6 + G, -1>, <4, 1.2, 1> }
    pigment { B } finish { F }
  }
  box { <-2, 0, -3.5>, <2, 0.5, -2> pigment { A } finish { F } }
  box { <-4, -1, 1.5>, <4, 0, 4> pigment { Floor } finish { F } }
#end
