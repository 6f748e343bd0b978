// expect: 4:25: 'O' is a object, not a texture, pigment, normal, finish or texture_map
#version 3.7;
#declare O = sphere { 0, 1 }
sphere { 0, 1 texture { O } }
