// expect: 3:48: area_light has too many samples (2000 x 2000; at most 1000000)
#version 3.7;
light_source { <0,5,0>, rgb 1 area_light x, z, 2000, 2000 }
