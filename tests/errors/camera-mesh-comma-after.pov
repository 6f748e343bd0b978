// expect: 5:27: expected a mesh or mesh2 object (a mesh camera needs at least one), found ','
// POV-Ray: "No matching } in 'mesh_camera', , found instead".
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1 0, mesh { M } } }
