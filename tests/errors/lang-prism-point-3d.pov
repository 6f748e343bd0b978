// expect: 4:32: a prism point is a 2-D vector <x, z>, found a 3-D vector
// POV-Ray: "UV_Vector expected but vector or color expression found."
#version 3.7;
prism { 0, 1, 4, <0,0>, <1,0>, <0,1,0>, <0,0> }
