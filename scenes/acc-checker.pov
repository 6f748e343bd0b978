// Accuracy sweep (tests/bench/accuracy.sh): a black and white checkerboard
// running to the horizon under a plain sky, the worst case for aliasing.
// Only the antialiasing switches vary (+A, +AM, +R, +J).
#version 3.7;
global_settings { assumed_gamma 1 }
camera { location <0,1,-5> look_at <0,0.6,10> angle 60 }
background { rgb <0.6,0.75,1> }
plane { y, 0 pigment { checker rgb 0 rgb 1 } finish { ambient 1 diffuse 0 } rotate y*20 }
