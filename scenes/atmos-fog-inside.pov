// atmos-fog-inside.pov: fog seen through see-through objects. As in POV-Ray
// 3.7, a ray keeps the list of interiors it has crossed into, and no fog
// lies on a segment while it is inside one that is not hollow: it counts
// crossings, whatever the geometry. Top row: behind a clear disc the fog
// is gone for good (the ray never crosses the disc again); in the union of
// two overlapping spheres the fog comes back in their overlap (the second
// sphere's surface leaves their shared interior); an open cylinder.
// Bottom row: thin glass panes (ior 1.5), solid and hollow; a hollow glass
// sphere around a solid clear one.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -8>
  right x*image_width/image_height
  look_at <0, 1, 0>
  angle 50
}

light_source { <-5, 10, -10> color rgb 1 }

plane { z, 8 pigment { checker color rgb <0.1, 0.2, 0.6> color rgb <0.9, 0.9, 0.3> } finish { ambient 0.6 diffuse 0.4 } hollow }
plane { y, -1.2 pigment { color rgb <0.5, 0.45, 0.4> } hollow }

fog { distance 9 color rgb <0.8, 0.85, 0.9> }

#declare Clear = texture { pigment { rgbf <0.9, 1, 0.95, 0.95> } finish { ambient 0 diffuse 0.1 } }
#declare Glass = texture { pigment { rgbf <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0 reflection 0.05 } }

disc { <-2.6, 2.3, 0>, -z, 0.9 texture { Clear } }
union {
  sphere { <-0.45, 0, 0>, 0.7 }
  sphere { <0.45, 0, 0>, 0.7 }
  texture { Clear }
  translate <0.2, 2.3, 0>
}
cylinder { <0, 0, -1>, <0, 0, 1>, 0.6 open texture { Clear } rotate <20, 35, 0> translate <2.6, 2.3, 0> }

box { <-0.8, -0.8, -0.03>, <0.8, 0.8, 0.03> texture { Glass } interior { ior 1.5 } rotate y*25 translate <-2.6, 0, 0> }
box { <-0.8, -0.8, -0.03>, <0.8, 0.8, 0.03> texture { Glass } interior { ior 1.5 } rotate y*25 translate <-0.4, 0, 0> hollow }
sphere { <2.3, 0, 0>, 0.9 texture { Glass } interior { ior 1.2 } hollow }
sphere { <2.3, 0, 0>, 0.45 texture { Clear } }
