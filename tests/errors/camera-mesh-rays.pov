// expect: 5:24: a mesh camera needs at least 1 ray per pixel, not 0.5
// POV-Ray: "Rays per pixel may not be 0" (it truncates 0.5).
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 0.5 0 mesh { M } } }
