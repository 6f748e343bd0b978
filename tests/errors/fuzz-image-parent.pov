// expect: 3:41: an image map may not read "../cli-signature.png": scene files can only read their own folder, the +L library paths and the stdlib (lucent --io-unrestricted lifts this)
// The file rule holds for image maps.
sphere { 0, 1 pigment { image_map { png "../cli-signature.png" } } }
