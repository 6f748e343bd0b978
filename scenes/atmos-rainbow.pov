// atmos-rainbow.pov: two rainbows over a background and ground plane: a
// full one with a colour map using filter and transmit, and an arc turned
// by its up vector with arc_angle and falloff_angle; a fog in front.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1, -5>
  right x*image_width/image_height
  look_at <0, 3, 0>
  angle 90
}

light_source { <-5, 10, -8> color rgb 1 }

background { color rgb <0.35, 0.45, 0.65> }
plane { y, 0 pigment { color rgb <0.3, 0.5, 0.25> } }

rainbow {
  direction <0, -0.2, 1>
  angle 42.5
  width 5
  distance 1e8
  color_map {
    [0.0 color rgbt <1, 0, 0, 0.3>]
    [0.3 color rgbf <1, 1, 0, 0.5>]
    [0.6 color rgb <0, 1, 0>]
    [1.0 color rgbft <0.3, 0.2, 1, 0.2, 0.4>]
  }
}
rainbow {
  direction <0, 0, 1>
  angle 25
  width 4
  distance 30
  up <1, 1, 0>
  arc_angle 140
  falloff_angle 60
  color_map { [0 color rgb <1, 0.5, 0>] [1 color rgb <0.5, 0, 1>] }
}
fog { distance 40 color rgb <0.7, 0.7, 0.7> }
