// atmos-fog-hollow.pov: which see-through objects hold fog. The camera is
// inside a clear sphere that is not hollow, so its rays see no fog until
// they leave it (POV-Ray: "fog will not work if the camera is inside a
// non-hollow object"). The leaves of one object share its interior, and
// the last of them decides for all whether it is hollow (measured in
// POV-Ray 3.7): in the top union the second sphere is solid, so fog stops
// inside both; in the bottom one it is hollow, so fog fills both, even
// under the union's `hollow off`. Right: a difference (a thick clear
// shell), solid, whose hole holds fog.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 0.8, -7>
  right x*image_width/image_height
  look_at <0, 0.8, 0>
  angle 50
}

light_source { <-5, 10, -10> color rgb 1 }

plane { z, 9 pigment { checker color rgb <0.1, 0.2, 0.6> color rgb <0.9, 0.9, 0.3> } finish { ambient 0.6 diffuse 0.4 } hollow }

fog { distance 7 color rgb <0.85, 0.8, 0.75> }

#declare Clear = texture { pigment { rgbf <1, 0.95, 0.9, 0.95> } finish { ambient 0 diffuse 0.1 } }

sphere { <0, 0.8, -7>, 2 texture { Clear } }
union {
  sphere { <-1.8, 0, 0>, 0.9 hollow }
  sphere { <0, 0, 0>, 0.9 }
  texture { Clear }
  translate <-0.6, 1.8, 0>
}
union {
  sphere { <-1.8, 0, 0>, 0.9 }
  sphere { <0, 0, 0>, 0.9 hollow }
  texture { Clear }
  hollow off
  translate <-0.6, -0.4, 0>
}
difference {
  sphere { 0, 1.2 }
  sphere { 0, 0.8 }
  texture { Clear }
  translate <2.6, 0.8, 0>
}
