// expect: 3:58: uv_mapping must come before the object's texture, pigment and normal
// POV-Ray: "uv_mapping must be specified before texture."
sphere { 0, 1 pigment { checker rgb 1 rgb 0 } finish { } uv_mapping }
