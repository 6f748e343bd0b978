// expect: 2:36: the minimum of blur_samples (10) is larger than the maximum (5)
camera { aperture 0.5 blur_samples 10, 5 }
