// expect: 5:24: a mesh camera needs at least 1 ray per pixel, not 0
// "1 -1" is one expression, 0: POV-Ray says "Rays per pixel may not be 0" too.
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 -1 mesh { M } } }
