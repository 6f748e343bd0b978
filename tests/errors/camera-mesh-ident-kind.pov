// expect: 6:35: 'V' is a vector, not an object
// A vector where a mesh identifier belongs.
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
#declare V = <1, 2, 3>;
camera { mesh_camera { 1 0 mesh { V } } }
