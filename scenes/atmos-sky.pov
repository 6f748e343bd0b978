// atmos-sky.pov: sky_sphere with layered gradient pigments (the upper one
// partly see-through), the sky turned by a rotation, emission, a pigment
// with its own transformation, seen directly and in a mirror; a declared
// sky_sphere used with one more rotation.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -5>
  right x*image_width/image_height
  look_at <0, 1.5, 0>
  angle 75
}

light_source { <-5, 10, -8> color rgb 1 }

#declare Sky = sky_sphere {
  pigment {
    gradient y
    color_map { [0.0 color rgb <0.9, 0.8, 0.6>] [0.5 color rgb <0.3, 0.5, 0.9>] [1.0 color rgb <0.05, 0.1, 0.4>] }
    scale 2 translate -1
  }
  pigment {
    gradient x
    color_map { [0.0 color rgbt <1, 1, 1, 1>] [0.5 color rgbft <1, 0.6, 0.6, 0.4, 0.3>] [1.0 color rgbt <1, 1, 1, 1>] }
    scale 0.5 rotate z*20
  }
  rotate x*-10
}
sky_sphere { Sky rotate x*-5 emission rgb <1.1, 1, 0.9> }

plane { y, 0 pigment { color rgb <0.5, 0.45, 0.4> } }
sphere { <0, 1.2, 1>, 1.2 pigment { color rgb 0.1 } finish { reflection 0.9 ambient 0 diffuse 0.1 } }
