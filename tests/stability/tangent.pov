// tangent.pov: rays exactly tangent to spheres and tori (run.sh: tangent,
// tangent-speckles). The camera is at the origin looking along +z and the
// image is 161x121, so the rays of the middle row lie exactly in the
// plane y = 0 and those of the middle column in the plane x = 0.
//   - Two tori lie flat (axis y) with their top circle, resp. bottom
//     circle, in the plane y = 0: every ray of the middle row that crosses
//     a torus is tangent to it (a double root of the quartic), along the
//     whole width of the torus.
//   - Two spheres touch the plane y = 0 from above and below, two touch
//     the plane x = 0 from either side.
// Declare=D=d moves every object by d towards the plane it touches (d > 0:
// the tangent rays cut into the objects; d < 0: they pass beside them).
// run.sh renders D = 0 and, as references, D = 1e-4 and D = -1e-4, a
// shift far below a pixel (about 1/500) but far above rounding, so the
// references have no tangent ray.
//
// Properties: (1) the D = 0 image equals one of the two references (all
// tangent rays hit, or all miss) up to 2 pixels over 0.03; (2) no
// speckle along the middle row and column: no pixel that differs by more
// than 0.1 from both its neighbours along the row (column) while they
// agree with each other; (3) no NaN or negative value (OpenEXR render).
//
// lucent passes. (It used to fail (1) and (2) on the tori: 31 of the 98
// tangent hits were shaded from the wrong side, because trace_ray turned
// the normal to face the ray whenever n.dir > 0, and for an exactly
// tangent ray n.dir is rounding noise. It now turns it only when
// n.dir > 1e-9, far above that noise.)
// POV-Ray 3.7 fails (1) and (2) as well, differently: its tangent rays
// hit (30) or miss (61) at random, and 7 hits are shaded wrong.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (D) #declare D = 0; #end

camera {
  location <0, 0, 0>
  direction z*1.2
  right x*image_width/image_height
  up y
}
light_source { <-3, 10, -4> color rgb 1 }
light_source { <3, -10, -4> color rgb 0.6 }
background { color rgb <0.1, 0.1, 0.3> }

#declare F = finish { ambient 0.15 diffuse 0.85 }
torus { 1.3, 0.3 translate <-1.7, -0.3 + D, 8> pigment { color rgb <1, 0.9, 0.3> } finish { F } }
torus { 1.3, 0.3 translate <1.7, 0.3 - D, 8> pigment { color rgb <0.6, 0.6, 1> } finish { F } }
sphere { <-0.55, 0.5 - D, 6>, 0.5 pigment { color rgb <1, 0.4, 0.3> } finish { F } }
sphere { <0.55, -0.5 + D, 6>, 0.5 pigment { color rgb <0.3, 1, 0.4> } finish { F } }
sphere { <0.6 - D, 1.8, 7>, 0.6 pigment { color rgb <1, 0.4, 1> } finish { F } }
sphere { <-0.6 + D, -1.8, 7>, 0.6 pigment { color rgb <0.4, 1, 1> } finish { F } }
