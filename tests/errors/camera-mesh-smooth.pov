// expect: 5:39: smooth applies to a mesh camera of distribution 3 only, not 2
// POV-Ray: "Smooth can only be used with distribution method #3".
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 2 mesh { M } smooth } }
