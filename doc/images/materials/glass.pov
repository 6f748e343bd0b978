// glass.pov: clear glass (ior 1.5 with fresnel reflection), green glass
// that darkens with thickness (fade_distance), and a ball with caustics.
#version 3.7;
#declare Stage_Floor = false;
#include "stage.inc"

plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.25 scale 0.5 } }
#declare Glass = finish { reflection { 0, 1 fresnel } conserve_energy phong 0.9 phong_size 80 };
sphere { <0, 0.5, 0>, 0.5 Slot(0, 3)
  pigment { rgbf <1, 1, 1, 1> } finish { Glass } interior { ior 1.5 } }
sphere { <0, 0.5, 0>, 0.5 Slot(1, 3)
  pigment { rgbf <1, 1, 1, 1> } finish { Glass }
  interior { ior 1.5 fade_distance 0.5 fade_power 1001 fade_color <0.2, 0.8, 0.4> } }
sphere { <0, 0.5, 0>, 0.5 Slot(2, 3)
  pigment { rgbf <1, 0.9, 0.7, 0.9> } finish { Glass } interior { ior 1.3 caustics 1 } }
