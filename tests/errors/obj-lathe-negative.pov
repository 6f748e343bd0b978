// A lathe point cannot have a negative radius (POV-Ray: "Incorrect point in lathe").
// expect: 3:40: a lathe point's radius (its first component) cannot be negative, found -1
lathe { bezier_spline 4, <1,0>, <3,1>, <-1,2>, <1,3> }
