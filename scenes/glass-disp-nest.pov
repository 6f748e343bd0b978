// glass-disp-nest.pov: dispersion among nested interiors, total internal
// reflection and the trace limits (doc/materials.md, Interiors). A
// dispersing ball inside a dispersing block (the bands the block splits
// refract into and out of the ball with the ball's ior at their hue); a
// dense dispersing cube whose bands reflect totally inside it, some
// escaping where others do not; and a mirror seen through a dispersing
// slab, with adc_bailout 0.2 and max_trace_level 6 cutting the paths.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 6 adc_bailout 0.2 }
camera { location <0, 2.2, -8> look_at <0, 1.1, 0> angle 46 }
light_source { <3, 9, -6>, rgb 1 }
background { rgb <0.15, 0.2, 0.3> }
plane { y, 0 pigment { checker rgb <0.9, 0.85, 0.8> rgb 0.05 scale 0.4 } finish { ambient 0.15 diffuse 0.8 } }
box { <-8, 0, 4>, <8, 6, 4.5>
  pigment { gradient x color_map { [0.5 rgb <0.1, 0.05, 0.02>] [0.5 rgb 1] } scale 0.5 }
  finish { ambient 0.25 diffuse 0.7 } }
// The block and the ball inside it.
box { <-1.1, 0.05, -0.7>, <1.1, 2.4, 0.7> rotate y*25 translate <-2.1, 0, 0.5>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.3 dispersion 1.1 dispersion_samples 4 } }
sphere { <-2.1, 1.2, 0.5>, 0.6
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.9 dispersion 1.3 } }
// The dense cube.
box { -0.7, 0.7 rotate <30, 40, 10> translate <0.4, 1.2, -1>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 2.1 dispersion 1.2 dispersion_samples 6 } }
// The slab and the mirror behind it.
box { <-0.7, 0, -0.05>, <0.7, 2.2, 0.05> rotate y*-30 translate <2.4, 0.1, -0.4>
  pigment { rgbf <0.9, 1, 0.8, 0.9> } finish { ambient 0 diffuse 0 reflection 0.1 }
  interior { ior 1.5 dispersion 1.5 dispersion_samples 3 } }
box { <-1, 0.01, -0.02>, <1, 2.6, 0.02> rotate y*20 translate <3, 0, 1.3>
  pigment { rgb 0.1 } finish { ambient 0.1 diffuse 0.3 reflection 0.6 } }
