// atmos-groundfog.pov: ground fog (fog_type 2) with fog_offset and
// fog_alt, its up vector turned by a rotation, and a second, constant fog
// layered with it (fogs act together). Rays that miss every object get
// the fog of their whole length too. The ground fog is a declared one,
// changed where it is used.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
  location <0, 2, -7>
  right x*image_width/image_height
  look_at <0, 1.2, 4>
  angle 65
}

light_source { <5, 12, -6> color rgb 1 }

background { color rgb <0.25, 0.4, 0.75> }

plane { y, 0 pigment { color rgb <0.4, 0.6, 0.3> } }

#for (I, 0, 4)
  cylinder { <-4 + 2*I, 0, 2 + 3*I>, <-4 + 2*I, 4, 2 + 3*I>, 0.4 pigment { color rgb <0.8, 0.7, 0.5> } }
#end
sphere { <0, 3, 8>, 1.5 pigment { color rgb <0.9, 0.3, 0.2> } }

#declare Ground = fog {
  fog_type 2
  distance 5
  color rgb <0.85, 0.85, 0.9>
  fog_offset 0.4
  fog_alt 0.8
  up <0, 1, 0>
  rotate z*8
}
fog { Ground distance 3 }
fog { distance 60 color rgbt <0.9, 0.7, 0.5, 0.2> }
