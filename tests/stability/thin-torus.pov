// thin-torus.pov: a torus of major radius 100 and minor radius 0.1, seen
// whole (run.sh: thin-torus-sturm, thin-torus-povray, thin-torus-exact).
// Seen from 120 units away at 240x180, the tube is 0.3 to 0.05 pixel
// wide: the ring shows as the pixels whose centre ray passes through the
// tube, most of them nearly tangent to it, which is where a quartic
// solver loses roots or finds false ones. Declare=STURM=1 adds sturm.
// The camera is given by direction, right and up (no look_at), so that
// check.py can rebuild every pixel's ray exactly.
//
// Properties: (1) without sturm and with sturm, identical up to 2 pixels
// over 1/255; (2) POV-Ray's render (tests/stability/povray/thin-torus.png)
// up to 2 pixels over 1/255; (3) exact: a pixel shows the torus if and
// only if its ray passes within 0.1 of the circle of radius 100, as
// check.py works out by minimising the distance along each ray (rays
// within 1e-4 of the tube's surface, none here, would not count).
//
// lucent passes all three: 240 pixels hit, the 240 predicted ones. So
// does POV-Ray 3.7, with and without sturm, identical to lucent.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (STURM) #declare STURM = 0; #end

camera {
  location <0, 20, -120>
  direction <0, -0.25, 1>*0.45
  right x*image_width/image_height
  up <0, 1, 0.25>
}
light_source { <30, 200, -100> color rgb 1 }
background { color rgb <0.05, 0.05, 0.15> }

torus { 100, 0.1 #if (STURM) sturm #end
  pigment { color rgb <1, 0.85, 0.4> } finish { ambient 0.3 diffuse 0.7 } }
