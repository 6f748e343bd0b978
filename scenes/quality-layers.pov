// quality-layers.pov: layered textures, a texture_map and a pigment_map with
// a quick_color at +Q0 (tests/render/sampling.list): POV-Ray shows each
// layer's pigment through the transparency of those above it, the last
// layer whole; at +Q2 and up layers and maps are shaded as at +Q9.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 50 right x*image_width/image_height }
light_source { <-4, 8, -5> color rgb 1 }
background { color rgb <0.3, 0.45, 0.7> }
plane { y, 0 texture { checker texture { pigment { rgb <1,0,0> } } texture { pigment { rgb <0,0,1> } } } }
sphere { <-1.5, 0.8, 0>, 0.8 texture { pigment { rgb <0.9, 0.9, 0.2> } } texture { pigment { bozo color_map { [0.5 rgbt <1,1,1,1>] [0.5 rgb <0,0.6,0>] } scale 0.2 } } }
sphere { <0.3, 0.8, 0>, 0.8 texture { gradient y texture_map { [0 pigment { rgb <1,0,1> }] [1 pigment { rgb <0,1,1> }] } } }
sphere { <2, 0.8, 0>, 0.8 pigment { gradient y pigment_map { [0 rgb <1,0.5,0>] [1 rgb <0,0.5,1>] } quick_color rgb <0.2,0.2,0.2> } }
