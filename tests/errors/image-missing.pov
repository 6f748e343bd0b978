// expect: 3:40: cannot find image file "no-such-image.png"
// expect-also: searched the scene's folder, the current folder and the +L paths
plane { z, 0 pigment { image_map { png "no-such-image.png" } } }
