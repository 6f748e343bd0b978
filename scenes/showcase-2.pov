// showcase-2.pov: a still life in glass, metal and stone. A glass goblet
// (CSG: a hollowed sphere cut open, a cylinder stem and a disc foot,
// merged), a solid glass ball with a tinted interior (fade_distance,
// fade_color), a mirror-chrome cylinder and a copper torus on a granite
// slab, in front of a wall in the brick pattern. Lit by an area light
// (5x5, adaptive 1, no jitter: deterministic) and a spotlight, under a
// sky_sphere seen through a distant constant fog. Exercises
// #include "colors.inc" (named colours), merge, difference and
// intersection, clipped_by, interiors with ior and fade, fresnel
// reflection, metallic highlights, granite and brick patterns,
// gradient-mapped sky_sphere, fog, area and spot lights, and
// max_trace_level.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#include "colors.inc"

camera {
  location <0.6, 2.6, -6.5>
  look_at <0, 0.9, 0>
  right x*image_width/image_height
  angle 42
}
sky_sphere {
  pigment { gradient y color_map { [0 color Orange*0.6] [0.3 color SkyBlue] [1 color MidnightBlue] } }
}
fog { distance 60 color rgbt <0.7, 0.75, 0.8, 0.2> }
light_source {
  <-6, 9, -7> color rgb 0.9
  area_light x*2, y*2, 5, 5 adaptive 1
}
light_source {
  <4, 6, -3> color rgb <1, 0.85, 0.6>
  spotlight point_at <0, 0.5, 0> radius 12 falloff 20 tightness 5
}

// the wall and the floor
box {
  <-8, -0.01, 3>, <8, 6, 3.5>
  pigment { brick color Gray80, color Firebrick brick_size <0.6, 0.25, 0.3> mortar 0.03 }
  finish { ambient 0.15 diffuse 0.8 }
}
plane { y, -0.6 pigment { color DarkSlateGray } finish { ambient 0.2 reflection 0.05 } }

// the slab: granite, its front corners cut by a cylinder (intersection)
intersection {
  box { <-3, -0.6, -1.6>, <3, 0, 2> }
  cylinder { <0, -1, 0>, <0, 1, 0>, 3.3 }
  pigment { granite color_map { [0 color Gray20] [0.5 color Gray60] [1 color Wheat] } scale 1.5 }
  finish { ambient 0.15 diffuse 0.75 specular 0.3 roughness 0.02 }
}

#declare Glass = material {
  texture {
    pigment { rgbt <0.98, 0.99, 1, 0.92> }
    finish { ambient 0 diffuse 0.05 specular 0.8 roughness 0.002 reflection { 0.02, 0.6 fresnel on } conserve_energy }
  }
  interior { ior 1.5 }
}
// the goblet: bowl (a sphere shell, cut open at the top), stem and foot
merge {
  difference {
    sphere { <0, 1.35, 0>, 0.6 }
    sphere { <0, 1.35, 0>, 0.56 }
    box { <-1, 1.65, -1>, <1, 2.5, 1> }
  }
  cylinder { <0, 0, 0>, <0, 0.8, 0>, 0.06 }
  cylinder { <0, 0, 0>, <0, 0.04, 0>, 0.4 }
  material { Glass }
  translate <-1.2, 0, 0.3>
}
// the ball: tinted glass whose colour deepens with thickness
sphere {
  <0.4, 0.45, -0.6>, 0.45
  material {
    texture { pigment { rgbf <1, 1, 1, 0.95> } finish { specular 0.6 roughness 0.003 reflection 0.05 } }
    interior { ior 1.45 fade_distance 0.5 fade_power 2 fade_color color SeaGreen }
  }
}
// chrome: a cylinder clipped into a half pipe standing on end
cylinder {
  <1.4, 0, 0.8>, <1.4, 1.6, 0.8>, 0.35
  clipped_by { plane { z, 0.9 } }
  pigment { color Gray70 }
  finish { ambient 0 diffuse 0.05 reflection { 0.85 metallic } specular 0.5 metallic }
}
// copper ring lying on the slab
torus {
  0.35, 0.08
  pigment { color Copper }
  finish { ambient 0.1 diffuse 0.5 specular 0.7 roughness 0.01 metallic reflection { 0.3 metallic } }
  translate <1.0, 0.08, -1.0>
}
