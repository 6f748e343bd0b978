// expect: 5:45: dispersion_samples must be from 2 to 2147483647, not 5.55556e+22
// Found by fuzzing (UBSan): the value was cast to int before any check of its
// range. POV-Ray's int cast makes it negative and refuses it ("Dispersion
// samples minimum is 2", measured with 1e12 and 3e9).
sphere { 0, 1 interior { dispersion_samples 55555555555555555555551 } }
