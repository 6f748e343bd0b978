// expect: 6:28: a mesh camera's mesh must be a mesh or mesh2 object
// POV-Ray 3.7 crashes here (no message); lucent refuses the sphere.
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
#declare S = sphere { 0, 1 }
camera { mesh_camera { 1 0 mesh { S } } }
