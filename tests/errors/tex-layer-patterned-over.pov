// expect: 6:3: cannot layer a patterned texture over another texture
// POV-Ray 3.7: "Cannot layer a patterned texture over another."
#version 3.7;
sphere { 0, 1
  texture { pigment { rgb 1 } }
  texture { uv_mapping pigment { rgbt 1 } } }
