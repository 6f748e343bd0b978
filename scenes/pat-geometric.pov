// pat-geometric.pov: the geometric pattern family, one pattern on the top
// of each of 16 tiles seen from above through the same colour map:
// hexagon, brick (with mortar and brick_size), cubic, square, triangular
// (colour lists) and gradient, radial (frequency), onion, leopard,
// spiral1, spiral2, quilted (control0/1), boxed, cylindrical, spherical,
// planar (colour maps, with a wave type each: ramp, sine, triangle,
// scallop, cubic, poly). No noise: every value is exact.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera {
  orthographic
  location <0, 10, 0>
  direction -y
  right x*8.4*image_width/image_height
  up z*8.4
}
light_source { <3, 12, -6> color rgb 1 }
background { rgb 0.05 }
#declare M = color_map {
  [0 rgb <0.9, 0.8, 0.5>] [0.25 rgb <0.2, 0.3, 0.7>] [0.5 rgb <0.8, 0.2, 0.1>]
  [0.75 rgb <0.1, 0.6, 0.3>] [1 rgb 1]
}
#macro T(I, J, P)
  box {
    <-0.95, -1, -0.95>, <0.95, 0, 0.95>
    pigment { P }
    finish { ambient 0.3 diffuse 0.7 }
    translate <(I - 1.5)*2, 0, (1.5 - J)*2>
  }
#end
T(0, 0, pigment { hexagon rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7>, rgb <0.8, 0.2, 0.1> scale 0.25 })
T(1, 0, pigment { brick rgb 0.8, rgb <0.7, 0.25, 0.1> brick_size <0.5, 0.2, 0.25> mortar 0.04 rotate x*90 })
T(2, 0, pigment { cubic rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7>, rgb <0.8, 0.2, 0.1>,
                        rgb <0.1, 0.6, 0.3>, rgb 1, rgb 0.3 rotate <30, 20, 10> })
T(3, 0, pigment { square rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7>, rgb <0.8, 0.2, 0.1>, rgb <0.1, 0.6, 0.3>
                  scale 0.3 rotate y*20 })
T(0, 1, pigment { triangular rgb <0.9, 0.8, 0.5>, rgb <0.2, 0.3, 0.7>, rgb <0.8, 0.2, 0.1>,
                  rgb <0.1, 0.6, 0.3>, rgb 1, rgb 0.3 scale 0.3 })
T(1, 1, pigment { gradient <1, 0, 1> color_map { M } frequency 2 ramp_wave translate x*0.013 })
T(2, 1, pigment { radial color_map { M } frequency 6 sine_wave rotate y*15 })
T(3, 1, pigment { onion color_map { M } scale 0.4 triangle_wave translate <0.3, 0, -0.2> })
T(0, 2, pigment { leopard color_map { M } scale 0.12 scallop_wave })
T(1, 2, pigment { spiral1 5 color_map { M } scale 0.5 rotate x*90 })
T(2, 2, pigment { spiral2 3 color_map { M } scale 0.5 rotate x*90 cubic_wave })
T(3, 2, pigment { quilted control0 0.2 control1 0.9 color_map { M } scale 0.5 poly_wave 2 })
T(0, 3, pigment { boxed color_map { M } scale 0.8 })
T(1, 3, pigment { cylindrical color_map { M } scale 0.8 rotate z*90 })
T(2, 3, pigment { spherical color_map { M } scale 0.9 frequency 2 })
T(3, 3, pigment { planar color_map { M } rotate x*60 scale 0.9 })
