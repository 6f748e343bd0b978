// The heights of a sor must increase (POV-Ray: "Incorrect point in surface of revolution").
// expect: 3:24: the heights of a sor's points must increase from the second point to the last but one: 1 follows 1
sor { 4, <0,0>, <1,1>, <1,1>, <1,2> }
