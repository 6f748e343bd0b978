// A height_field image that is not there.
// expect: 3:20: cannot find height_field image "no-such-file.png" (searched the scene's folder, the current folder and the +L paths)
height_field { png "no-such-file.png" }
