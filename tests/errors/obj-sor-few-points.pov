// A sor needs four points (POV-Ray: "Surface of revolution must have at least four points").
// expect: 3:7: a sor needs at least 4 points, found 3
sor { 3, <0,0>, <1,1>, <1,2> }
