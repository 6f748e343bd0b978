// checks that global_settings { noise_generator } is the generator of the patterns read after it, unless they name their own
#version 3.7;
global_settings { assumed_gamma 1 noise_generator 1 }
#declare F1 = function { pattern { bozo } }
#declare F2 = function { pattern { bozo noise_generator 2 } }
#declare F3 = function { pattern { gradient x warp { turbulence 0.5 } } }
#declare F4 = function { pigment { bumps color_map { [0 rgb 0] [1 rgb 1] } } }
#debug concat(str(F1(0.3, 0.4, 0.5), 0, 9), " ", str(F2(0.3, 0.4, 0.5), 0, 9), " ", str(F3(0.3, 0.4, 0.5), 0, 9), " ", str(F4(1.3, -0.4, 0.5).red, 0, 9), "\n")
global_settings { noise_generator 3 }
#declare F5 = function { pattern { bozo noise_generator 1 } }
#debug concat(str(F5(0.3, 0.4, 0.5), 0, 9), "\n")
