// expect: 5:24: distribution 0 needs a mesh per ray: 2 rays per pixel but 1 mesh
// POV-Ray: "Rays per pixel must be <= number of meshes" (distribution 0).
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 2 0 mesh { M } } }
