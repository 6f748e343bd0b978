// expect: 4:25: function P gives a color: name a component (.red, .green, .blue, .filter, .transmit, .gray or .x, .y, .z, .t)
#version 3.7;
#declare P = function { pigment { rgb 1 } }
#declare F = function { P(x, y, z) + 1 }
