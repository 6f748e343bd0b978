// expect: 3:31: expected an object, light_source, global_lights, a transformation or '}', found 'pigment'
#version 3.7;
light_group { sphere { 0, 1 } pigment { rgb 1 } }
