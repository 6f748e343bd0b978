// expect: 4:14: an sRGB color (srgbt) cannot be used before global_settings { assumed_gamma } is set
// The same for every sRGB keyword, and without a #version.
#declare A = rgb 1;
#declare C = srgbt <0.5, 0.2, 0.1, 0.5>;
global_settings { assumed_gamma 1 }
