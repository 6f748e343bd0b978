// bench-spheres.pov: 100,000 spheres placed by a macro in a #while loop
// with rand, over a plane: the parse benchmark of placed objects and the
// render benchmark of a large flat hierarchy.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 14, -22> right x*image_width/image_height look_at <0, 0, 0> angle 60 }
light_source { <20, 40, -30> color rgb 1 }
background { color rgb <0.1, 0.1, 0.15> }
plane { y, 0 pigment { color rgb 0.6 } }
#declare R = seed(42);
#macro Ball(P, Rad, C)
  sphere { P, Rad pigment { color C } finish { phong 0.3 } }
#end
#declare I = 0;
#while (I < 100000)
  Ball(<40 * rand(R) - 20, 3 * rand(R), 40 * rand(R) - 20>, 0.05 + 0.1 * rand(R),
       rgb <rand(R), rand(R), rand(R)>)
  #declare I = I + 1;
#end
