// aa-lines.pov: antialiasing test for the recursive method (+AM2). A fan
// of thin bright rods over a dark floor (edges at every angle, rods
// narrower than a pixel far away), small spheres, a soft gradient that
// must not be subdivided, and a radial pattern converging to a point
// (detail finer than any subdivision). Rendered without jitter (-J) in
// tests/render/sampling.list.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -6> look_at <0, 0, 0> angle 50 right x*image_width/image_height }
light_source { <2, 8, -4> color rgb 1 }
background { color rgb <0.02, 0.02, 0.05> }
plane { y, 0 pigment { gradient x color_map { [0 rgb <0.05, 0.05, 0.1>] [1 rgb <0.3, 0.2, 0.1>] } scale 12 translate -6*x } }
#declare I = 0;
#while (I < 12)
  cylinder { <0, 0.05, 0>, <6, 0.05, 0>, 0.02 rotate y*(I*15 - 80)
    pigment { color rgb <1, 0.9 - I*0.05, 0.3 + I*0.05> } finish { ambient 1 diffuse 0 } }
  sphere { <1.2, 0.08, 0>, 0.08 rotate y*(I*15 - 73) pigment { color rgb <0.2, 0.6, 1> } }
  #declare I = I + 1;
#end
disc { <-1.7, 0.9, 1.5>, <0.3, 0.5, -1>, 0.7 pigment { radial frequency 24 color_map { [0.5 rgb 1] [0.5 rgb 0] } rotate x*90 translate <-1.7, 0.9, 1.5> } finish { ambient 1 diffuse 0 } }
