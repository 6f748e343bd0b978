// expect: 3:32: expected pigment, emission, a transformation or '}', found 'finish'
#version 3.7;
sky_sphere { pigment { rgb 1 } finish { ambient 1 } }
