// expect: 3:45: noise_generator must be from 1 to 3, not 4
#version 3.7;
#declare P = pigment { bozo noise_generator 4 }
