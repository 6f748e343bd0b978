// expect: 3:51: area_light sizes must be at least 1, not -2
#version 3.7;
light_source { <0,5,0>, rgb 1 area_light x, z, 3, -2 }
