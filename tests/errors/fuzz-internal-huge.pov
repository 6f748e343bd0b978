// expect: 5:25: there is no internal function 1e+105
// Found by fuzzing: internal()'s number was cast to int before it was
// checked (UBSan: 1e105 outside the range of int).
#version 3.7;
#declare F = function { internal(1e105) }
