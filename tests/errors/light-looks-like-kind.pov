// expect: 4:38: 'S' is a float, not an object
#version 3.7;
#declare S = 1;
light_source { 0, rgb 1 looks_like { S } }
