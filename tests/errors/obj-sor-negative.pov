// A sor point cannot have a negative radius (POV-Ray: "Incorrect point in surface of revolution").
// expect: 3:17: a sor point's radius (its first component) cannot be negative, found -1
sor { 4, <0,0>, <-1,1>, <1,2>, <1,3> }
