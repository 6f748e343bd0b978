// expect: 6:3: cannot layer a finish over a patterned texture
// POV-Ray 3.7: "Cannot layer over a patterned texture." (a texture-level
// uv_mapping makes the texture patterned).
#version 3.7;
sphere { 0, 1 texture { uv_mapping pigment { checker rgb 1 rgb 0 } }
  finish { ambient 1 } }
