// expect: 2:72: blur_samples must be at most 2147483647, not 3e+09
camera { location -5*z look_at 0 aperture 1 focal_point 0 blur_samples 3e9 }
