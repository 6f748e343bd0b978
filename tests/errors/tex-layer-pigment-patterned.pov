// expect: 6:3: cannot layer a pigment over a patterned texture
// POV-Ray 3.7: "Cannot layer over a patterned texture."
#version 3.7;
sphere { 0, 1
  texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }
  pigment { rgb 0.5 } }
