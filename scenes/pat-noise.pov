// pat-noise.pov: the noise pattern family as pigments, one on the top of
// each of 12 tiles seen from above through the same colour map: bozo,
// spotted, granite, marble and wood (with turbulence), agate
// (agate_turb), wrinkles, bumps and dents as pigments, ripples and waves
// (frequency, phase), and a bozo with the three noise generators side by
// side (noise_generator 1, 2 and 3 on three strips of the last tile).
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
  [0 rgb <0.1, 0.1, 0.2>] [0.3 rgb <0.2, 0.3, 0.7>] [0.5 rgb <0.8, 0.2, 0.1>]
  [0.75 rgb <0.9, 0.8, 0.5>] [1 rgb 1]
}
#macro T(I, J, P)
  box {
    <-0.95, -1, -0.95>, <0.95, 0, 0.95>
    pigment { P }
    finish { ambient 0.3 diffuse 0.7 }
    translate <(I - 1.5)*2, 0, (1 - J)*2>
  }
#end
T(0, 0, pigment { bozo color_map { M } scale 0.3 })
T(1, 0, pigment { spotted color_map { M } scale 0.2 })
T(2, 0, pigment { granite color_map { M } scale 1.5 })
T(3, 0, pigment { marble color_map { M } turbulence 0.8 scale 0.6 })
T(0, 1, pigment { wood color_map { M } turbulence 0.1 scale 0.15 rotate x*70 })
T(1, 1, pigment { agate agate_turb 0.6 color_map { M } scale 0.5 })
T(2, 1, pigment { wrinkles color_map { M } scale 0.4 })
T(3, 1, pigment { bumps color_map { M } scale 0.2 })
T(0, 2, pigment { dents color_map { M } scale 0.3 })
T(1, 2, pigment { ripples color_map { M } frequency 3 phase 0.2 scale 0.5 })
T(2, 2, pigment { waves color_map { M } frequency 2 scale 0.5 })
T(3, 2, pigment {
  gradient x
  pigment_map {
    [0.33 bozo noise_generator 1 color_map { M } scale 0.2]
    [0.33 bozo noise_generator 2 color_map { M } scale 0.2]
    [0.67 bozo noise_generator 2 color_map { M } scale 0.2]
    [0.67 bozo noise_generator 3 color_map { M } scale 0.2]
  }
  scale 1.9 translate -x*0.95
})
