// expect: 2:72: palette index 6 is out of range: "
plane { z, 0 pigment { image_map { png "../data/images/pal.png" filter 6, 0.5 } } }
