// expect: 2:45: dispersion_samples must be at least 2
sphere { 0, 1 interior { dispersion_samples 1 } }
