// uv-mapping.pov: uv_mapping written inside a pigment or normal block
// (pigment { uv_mapping ... }), not only at the texture level, on a sphere,
// a box, a mesh2 with uv_vectors and a layered texture; the transformations
// written after the uv-mapped block (the object's, a texture identifier's)
// leave it glued to the surface, as in POV-Ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2.2, -6.5>
  right x*image_width/image_height
  look_at <0, 0.6, 0>
  angle 42
}

light_source { <-4, 8, -7> color rgb 1 }
background { color rgb <0.25, 0.35, 0.55> }

#declare Check = pigment { uv_mapping checker rgb <0.9, 0.9, 0.85> rgb <0.8, 0.15, 0.1> scale <0.125, 0.25, 1> }

// A sphere: the identifier keeps its uv_mapping; the texture's scale and
// the object's rotation do not move it.
sphere { 0, 1
  texture { pigment { Check } scale 3 }
  rotate y*35
  translate <-2.1, 1, 0.6>
}

// A box, pigment-level uv_mapping with a pattern transformed in its block,
// and a normal { uv_mapping }.
box { -0.8, 0.8
  pigment { uv_mapping gradient x color_map { [0 rgb <0.1, 0.3, 0.8>] [1 rgb <0.95, 0.9, 0.3>] } scale 0.25 rotate z*30 }
  normal { uv_mapping ripples 0.5 scale 0.1 }
  rotate <25, -30, 0>
  translate <0, 0.8, -0.2>
}

// A mesh2 with uv_vectors, with two layers: uv-mapped stripes with
// transparent gaps over a uv-mapped checker.
mesh2 {
  vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.2, 0> }
  uv_vectors { 5, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0.5, 0.5> }
  face_indices { 4, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4> }
  texture { pigment { uv_mapping checker rgb <0.2, 0.7, 0.3> rgb <0.95, 0.95, 0.9> scale 0.2 } }
  texture { pigment { uv_mapping gradient y color_map { [0 rgbt <0.1, 0.1, 0.6, 0>] [0.5 rgbt <0.1, 0.1, 0.6, 0>] [0.5 rgbt 1] [1 rgbt 1] } scale 0.1 } }
  scale 0.9
  rotate y*20
  translate <2.1, 0.2, 0.3>
}

plane { y, 0 pigment { checker rgb 0.8 rgb 0.6 } }
