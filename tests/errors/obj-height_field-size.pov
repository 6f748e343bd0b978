// A height_field function needs at least 2 x 2 samples (POV-Ray needs a grid to make triangles).
// expect: 3:28: a height_field function's height must be from 2 to 65536, found 1
height_field { function 4, 1 { x } }
