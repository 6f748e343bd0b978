// expect: 2:36: blur_samples must be at least 1, not 0
camera { aperture 0.5 blur_samples 0 }
