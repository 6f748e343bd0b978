// expect: 5:79: a pavement of 4 squares has 5 patterns, not 6
// POV-Ray: "pattern value for pavement is out of range. max per tile:(1,2,5,12,35)"
// (checked when the pigment ends: the pattern may come before number_of_tiles)
#version 3.7;
plane { y, 0 pigment { pavement pattern 6 number_of_tiles 4 number_of_sides 4 } }
