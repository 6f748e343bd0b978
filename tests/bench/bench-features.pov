// bench-features.pov: the feature benchmark (tests/bench/features.sh). A
// matte scene: 2,000 diffuse spheres on a plane under one light. With
// Declare=MIRROR=1 one sphere in the middle becomes a mirror, which turns
// reflection on for the whole render. With Declare=AA=... nothing changes
// in the scene: the script varies the switches.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#ifndef (MIRROR) #declare MIRROR = 0; #end
camera { location <0, 8, -16> right x*image_width/image_height look_at <0, 0, 0> angle 55 }
light_source { <20, 40, -30> color rgb 1 }
background { color rgb <0.2, 0.3, 0.5> }
plane { y, 0 pigment { color rgb 0.6 } }
#declare R = seed(7);
#declare I = 0;
#while (I < 2000)
  sphere { <30 * rand(R) - 15, 0.2, 30 * rand(R) - 15>, 0.1 + 0.15 * rand(R)
    pigment { color rgb <rand(R), rand(R), rand(R)> } }
  #declare I = I + 1;
#end
#if (MIRROR)
  sphere { <0, 1.5, 0>, 1.5 pigment { color rgb 0.1 } finish { reflection 0.8 } }
#else
  sphere { <0, 1.5, 0>, 1.5 pigment { color rgb 0.1 } }
#end
