// expect: 2:12: a #default texture cannot be patterned (a texture_map, or a block pattern of textures), as in POV-Ray
#default { texture { gradient x texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }
