// expect: 3:48: area_light sizes must be at least 1, not 0
#version 3.7;
light_source { <0,5,0>, rgb 1 area_light x, z, 0, 3 }
