// expect: 3:1: a sky_sphere needs at least one pigment
#version 3.7;
sky_sphere { rotate x*20 }
