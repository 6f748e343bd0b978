// aa-checker.pov: antialiasing test. A high-contrast checker plane seen at
// grazing angles (edges at every slope, moire towards the horizon), a
// sphere's silhouette, a thin cylinder narrower than a pixel in places and
// a bright emitter (colours above 1, averaged unclipped). Rendered without
// jitter (-J) with +AM1 and +AM2 in tests/render/sampling.list.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.2, -5> look_at <0, 0.6, 0> angle 60 right x*image_width/image_height }
light_source { <-3, 6, -4> color rgb 1 }
background { color rgb <0.05, 0.1, 0.3> }
plane { y, 0 pigment { checker color rgb 1 color rgb 0.02 } rotate y*23
  finish { ambient 0.1 diffuse 0.8 } }
sphere { <-1.2, 0.7, 0.5>, 0.7 pigment { color rgb <0.9, 0.3, 0.1> } finish { phong 0.8 phong_size 60 } }
cylinder { <0.2, 0.02, -1>, <1.6, 1.4, 1.5>, 0.012 pigment { color rgb <0.2, 1, 0.3> } finish { ambient 1 diffuse 0 } }
box { <0.9, 0, -1.6>, <1.3, 0.25, -1.2> rotate y*35 pigment { color rgb <3, 2.5, 1> } finish { ambient 1 diffuse 0 } }
