// expect: 3:45: expected an object in projected_through, found '}'
#version 3.7;
light_source { 0, rgb 1 projected_through { } }
