// expect: 4:7: 'T' is a texture, not a fog
#version 3.7;
#declare T = texture { pigment { rgb 1 } }
fog { T distance 5 }
