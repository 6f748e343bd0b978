// mat-uv-object.pov: `uv_mapping` as an object modifier (POV-Ray 3.7 takes
// it before the object's texture): the pigments, normals and textures
// given after it are uv-mapped, as if each began with uv_mapping. Left: a
// sphere with a uv-mapped checker pigment and a finish after it (a finish
// may follow, since only the pigment is uv-mapped); middle: a box with a
// uv-mapped texture; right: a torus with a uv-mapped gradient pigment and
// a uv-mapped bumps normal.
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0, 1.5, -7> look_at <0, 0, 0> angle 50 }
light_source { <-5, 8, -10>, rgb 1 }
background { rgb 0.15 }
sphere { <-2.3, 0, 0>, 1
  uv_mapping
  pigment { checker rgb <0.9, 0.2, 0.1> rgb <0.95, 0.9, 0.8> scale <0.125, 0.25, 1> }
  finish { phong 0.4 }
}
box { -0.8, 0.8 rotate <-20, 30, 0>
  uv_mapping
  texture { pigment { gradient x color_map { [0 rgb <0.1, 0.3, 0.9>] [1 rgb <0.9, 0.9, 0.2>] } } finish { ambient 0.2 } }
}
torus { 0.8, 0.3 rotate -70 * x translate <2.3, 0, 0>
  uv_mapping
  pigment { gradient y color_map { [0 rgb <0.2, 0.8, 0.3>] [0.5 rgb <0.9, 0.9, 0.9>] [1 rgb <0.2, 0.8, 0.3>] } }
  normal { bumps 0.6 scale 0.05 }
}
