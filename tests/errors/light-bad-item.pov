// expect: 3:25: expected a light_source item or '}', found 'phong'
#version 3.7;
light_source { 0, rgb 1 phong 1 }
