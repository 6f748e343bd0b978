// glass-disp-prism.pov: dispersion as POV-Ray 3.7 does it (doc/materials.md,
// Interiors). A prism, a ball and a slab, each dispersing by its own
// amount and number of samples, in front of a lit black and white
// striped wall: each shows the stripes' edges split into the bands of the
// spectrum. The ball behind the prism and the slab in front of the ball
// receive rays that are bands already: they refract them with their own
// ior at the band's hue and split them no more. The ball has fresnel
// reflection, the slab a tinted filter.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 10 }
camera { location <0, 1.5, -8> look_at <0, 1.2, 0> angle 44 }
light_source { <-3, 8, -7>, rgb 1 }
background { rgb <0.2, 0.25, 0.35> }
plane { y, 0 pigment { checker rgb 0.05 rgb 0.95 scale 0.5 } finish { ambient 0.1 diffuse 0.8 } }
box { <-8, 0, 3>, <8, 6, 3.5>
  pigment { gradient x color_map { [0.5 rgb 0.02] [0.5 rgb 1] } scale 0.6 }
  finish { ambient 0.2 diffuse 0.8 } }
// A triangular prism standing on its end, edge towards the camera.
prism { linear_sweep linear_spline 0, 2.4, 4, <0, -0.9>, <0.8, 0.5>, <-0.8, 0.5>, <0, -0.9>
  translate <-1.9, 0.1, 0>
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.5 dispersion 1.25 dispersion_samples 5 } }
// Behind the prism's right half, seen through it: another dispersing ball.
sphere { <-1.2, 1.2, 1.6>, 0.6
  pigment { rgbf <1, 1, 1, 0.97> } finish { ambient 0 diffuse 0 reflection { 0, 1 fresnel } }
  interior { ior 1.6 dispersion 1.4 dispersion_samples 3 } }
// A ball with a smooth spectrum (40 bands).
sphere { <1.5, 1.1, 0>, 1
  pigment { rgbf 1 } finish { ambient 0 diffuse 0 }
  interior { ior 1.45 dispersion 1.12 dispersion_samples 40 } }
// A tilted slab over the ball's right side, two bands.
box { <-0.4, -1, -0.08>, <0.4, 1, 0.08> rotate <0, -35, 20> translate <2.1, 1.3, -1.6>
  pigment { rgbf <1, 0.9, 0.7, 0.9> } finish { ambient 0 diffuse 0 }
  interior { ior 1.7 dispersion 1.3 dispersion_samples 2 } }
