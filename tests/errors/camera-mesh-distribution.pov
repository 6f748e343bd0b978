// expect: 5:26: a mesh camera's distribution type must be 0, 1, 2 or 3, not 4
// POV-Ray: "Unrecognized distribution method".
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 4 mesh { M } } }
