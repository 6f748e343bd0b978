// pat-fractal-warps.pov: the fractal patterns and the warps, one on the
// top of each of 12 tiles seen from above. Fractals: mandel (exterior and
// interior types), julia (with its complex constant, exponent 3), magnet
// (type 1 mandel, type 2 julia). Warps on a checker or gradient: repeat
// with flip and offset, black_hole (strength, falloff, inverse), the
// turbulence warp (octaves, omega, lambda), cylindrical, spherical and
// toroidal mapping warps, planar, and a pigment_map blending patterns.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  orthographic
  location <0, 10, 0>
  direction -y
  right x*8.4*image_width/image_height
  up z*6.3
}
light_source { <3, 12, -6> color rgb 1 }
background { rgb 0.05 }
#declare M = color_map {
  [0 rgb 0] [0.15 rgb <0.2, 0.3, 0.7>] [0.35 rgb <0.8, 0.2, 0.1>]
  [0.6 rgb <0.9, 0.8, 0.5>] [1 rgb 1]
}
#declare C = pigment { checker rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7> scale 0.25 }
#macro T(I, J, P)
  box {
    <-0.95, -1, -0.95>, <0.95, 0, 0.95>
    pigment { P }
    finish { ambient 0.3 diffuse 0.7 }
    translate <(I - 1.5)*2, 0, (1 - J)*2>
  }
#end
T(0, 0, pigment { mandel 30 exterior 1, 1 color_map { M } scale 0.6 rotate x*90 translate x*0.3 })
T(1, 0, pigment { mandel 25 exponent 3 interior 2, 1 color_map { M } scale 0.6 rotate x*90 })
T(2, 0, pigment { julia <0.353, 0.288>, 40 color_map { M } scale 0.5 rotate x*90 })
T(3, 0, pigment { magnet 1 mandel 20 color_map { M } scale 0.4 rotate x*90 translate x*0.5 })
T(0, 1, pigment { magnet 2 julia <0.5, 0.3>, 20 color_map { M } scale 0.9 rotate x*90 })
T(1, 1, pigment { C warp { repeat x*0.5 flip x offset z*0.1 } })
T(2, 1, pigment { C warp { black_hole <0.2, 0, 0.1>, 0.7 strength 1.5 falloff 2 } })
T(3, 1, pigment { C warp { black_hole <0, 0, 0>, 0.6 strength 1 inverse } })
T(0, 2, pigment { C warp { turbulence 0.4 octaves 3 omega 0.6 lambda 2.5 } })
T(1, 2, pigment { gradient x color_map { M } frequency 4 warp { cylindrical orientation y dist_exp 1 } scale 0.5 })
T(2, 2, pigment { checker rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7> scale <0.25, 0.1, 0.25> warp { spherical orientation z dist_exp 0.5 } scale 0.8 })
T(3, 2, pigment {
  gradient z
  pigment_map {
    [0 C]
    [0.5 gradient x color_map { M } frequency 3 warp { toroidal major_radius 0.5 }]
    [1 onion color_map { M } scale 0.3 warp { planar y, 0.2 }]
  }
  translate z*0.5 scale 1.9 translate -z*0.95
})
