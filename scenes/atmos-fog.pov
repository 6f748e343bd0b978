// atmos-fog.pov: constant fog (fog_type 1) over a ground plane and spheres
// at several distances: a fog colour with filter and transmit, a mirror
// that sees fog along its reflected rays, a glass sphere whose inside gets
// no fog (it is not hollow) and a hollow one whose inside does.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 1.5, -6>
  right x*image_width/image_height
  look_at <0, 1, 4>
  angle 60
}

light_source { <-5, 10, -8> color rgb 1 }

background { color rgb <0.3, 0.45, 0.7> }

plane { y, 0 pigment { checker color rgb <0.8, 0.75, 0.7> color rgb <0.3, 0.3, 0.35> scale 2 } }

sphere { <-2.5, 1, 0>, 1 pigment { color rgb <0.9, 0.2, 0.1> } }
sphere { <0, 1, 6>, 1 pigment { color rgb <0.2, 0.8, 0.3> } }
sphere { <2.5, 1, 14>, 1 pigment { color rgb <0.2, 0.3, 0.9> } }
sphere { <1.2, 0.7, -1>, 0.7 pigment { color rgb 0.1 } finish { reflection 0.8 ambient 0 diffuse 0.1 } }
sphere { <-0.9, 0.6, -2.5>, 0.6 pigment { color rgbt <1, 1, 1, 0.9> } }
sphere { <3.2, 1.2, 3>, 1.2 pigment { color rgbt <1, 1, 1, 0.9> } hollow }

fog { distance 12 color rgbft <0.75, 0.78, 0.8, 0.3, 0.1> }
