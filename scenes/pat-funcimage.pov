// pat-funcimage.pov: images computed from functions: image_map { function
// W, H { ... } } from a float function, a pattern and a pigment, and an
// image_pattern and interpolated image_map made the same way.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -10> look_at <0, 0, 0> angle 36 }
light_source { <-3, 5, -10> color rgb 1 }
#macro B(P, X, Y)
  box { <0.002, 0.002, 0>, <0.998, 0.998, 0.1> pigment { P } finish { ambient 0.3 diffuse 0.7 } translate <-0.5, -0.5, 0> scale 2.13 translate <X + 0.0123, Y + 0.0071, 0> }
#end
B(pigment { image_map { function 48, 48 { sin(x*9)*cos(y*7)*0.5 + 0.5 } } }, -2.4, 1.2)
B(pigment { image_map { function 32, 24 { pattern { bozo scale 0.2 } } interpolate 2 } }, 0, 1.2)
B(pigment { image_map { function 40, 40 { pigment { radial frequency 5 color_map { [0 rgb <1, 0.5, 0>] [1 rgb <0, 0.3, 1>] } translate <0.5, 0.5, 0> } } } }, 2.4, 1.2)
B(pigment { image_pattern { function 32, 32 { x * y } } color_map { [0 rgb <0.1, 0.2, 0.5>] [1 rgb 1] } }, -2.4, -1.2)
B(pigment { image_map { function 16, 16 { 1.5 * x - 0.3 } once } }, 0, -1.2)
B(pigment { image_map { function 24, 24 { pigment { checker rgbt <1, 0, 0, 0.5> rgb <1, 1, 0> scale 0.25 } } } }, 2.4, -1.2)
