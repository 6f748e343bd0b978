// expect: 4:14: 'F' is a fog, not a sky_sphere
#version 3.7;
#declare F = fog { distance 5 color rgb 1 }
sky_sphere { F }
