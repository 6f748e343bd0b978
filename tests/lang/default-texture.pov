// checks that #default with texture, pigment, normal and finish items parses and leaves identifiers alone
#version 3.7;
#declare Original_Default = texture {}
#default {
  texture {
    pigment { rgb <1,0,0> }
    normal { bumps 0.3 }
    finish { ambient 0.4 }
  }
}
#default { pigment { rgb <0, 1, 0> } }
#default { finish { diffuse 0.5 } }
#default { normal { dents 0.1 } }
#default { texture { Original_Default } }
#debug "defaults changed and restored\n"
