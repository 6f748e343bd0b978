// checks srgb conversion to linear values (exact sRGB transfer curve)
#version 3.7;
global_settings { assumed_gamma 1.0 }
#declare A = srgb <0.5, 0.2, 0.04045>;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = srgb <0, 1, 0.01>;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = srgb 0.5;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = srgb <0.25, 0.75, 0.9>;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
