// Accuracy sweep (tests/bench/accuracy.sh): refraction and reflection
// through nested glass in front of a checkered floor and wall, where each
// extra bounce still changes the image. MTL sets max_trace_level [5].
#version 3.7;
#ifndef (MTL) #declare MTL = 5; #end
global_settings { assumed_gamma 1 max_trace_level MTL }
camera { location <0,2.2,-6> look_at <0,0.9,0> angle 40 }
light_source { <-4,8,-6>, rgb 1 }
light_source { <5,4,-3>, rgb 0.4 }
plane { y, 0 pigment { checker rgb <0.9,0.2,0.1> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
plane { z, 4 pigment { checker rgb <0.1,0.3,0.9> rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
#declare Glass = material {
  texture { pigment { rgbf <0.95,1,0.97,0.95> } finish { ambient 0 diffuse 0 specular 0.6 roughness 0.002 reflection { 0.05, 0.6 fresnel on } conserve_energy } }
  interior { ior 1.5 }
}
sphere { <-0.9,1,0>, 1 material { Glass } }
difference {
  sphere { <1.2,0.8,0.4>, 0.8 }
  sphere { <1.2,0.8,0.4>, 0.6 }
  material { Glass }
}
box { <-0.4,0.01,-0.4>, <0.4,0.81,0.4> rotate y*30 translate <0.3,0,-2> material { Glass } }
