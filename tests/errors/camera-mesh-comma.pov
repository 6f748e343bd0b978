// expect: 5:25: expected an expression, found ','
// POV-Ray: "Expected 'numeric expression', , found instead": no commas.
#version 3.7;
#declare M = mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } }
camera { mesh_camera { 1, 0 mesh { M } } }
