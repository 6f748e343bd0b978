// Lathe points are 2-D (POV-Ray: "UV_Vector expected but vector or color expression found").
// expect: 3:26: a lathe point is a 2-D vector, found a 3-D vector
lathe { 3, <0,0>, <1,0>, <1,1,3> }
