// expect: 4:25: an sRGB color (srgb) cannot be used before global_settings { assumed_gamma } is set
// POV-Ray: "Cannot parse sRGB colors before assumed_gamma has been set."
#version 3.7;
sphere { 0, 1 pigment { srgb <0.5, 0.2, 0.1> } }
global_settings { assumed_gamma 1 }
