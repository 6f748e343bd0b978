// expect: 3:95: cannot layer a texture over a patterned texture
#version 3.7;
sphere { 0, 1 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } texture { pigment { rgbt 1 } } }
