// expect: 4:26: 'T' is a texture, not a material
#version 3.7;
#declare T = texture { pigment { rgb 1 } }
sphere { 0, 1 material { T } }
