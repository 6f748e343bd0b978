// expect: 5:28: expected a mesh or mesh2 object (a mesh camera needs at least one), found '}'
// POV-Ray: "Expected 'mesh or mesh2', } found instead".
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 0 } }
