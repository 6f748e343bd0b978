// expect: 2:77: interpolate must be 2 (bilinear), 3 (bicubic) or 4 (normalized distance), not 1
plane { z, 0 pigment { image_map { png "../data/images/rgb.png" interpolate 1 } } }
