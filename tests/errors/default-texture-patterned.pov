// expect: 2:12: a #default texture cannot be patterned (a texture_map, or a block pattern of textures), as in POV-Ray
#default { texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }
