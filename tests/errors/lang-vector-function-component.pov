// expect: 5:25: function T gives a vector: name a component (.red, .green, .blue, .filter, .transmit, .gray or .x, .y, .z, .t)
// POV-Ray: "Expected '.', } found instead" (a vector function in a float function needs a component)
#version 3.7;
#declare T = function { transform { scale 2 } }
#declare F = function { T(x, y, z) }
