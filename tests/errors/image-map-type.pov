// expect: 2:74: map_type must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), not 3
plane { z, 0 pigment { image_map { png "../data/images/rgb.png" map_type 3 } } }
