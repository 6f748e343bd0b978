// expect: 5:24: distribution 2 takes 1 ray per pixel, not 2
// POV-Ray: "Rays per pixel must be 1 for distribution method #2".
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 2 2 mesh { M } mesh { M } } }
