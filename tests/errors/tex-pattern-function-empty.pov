// expect: 3:45: a pattern function needs a pattern
#version 3.7;
#declare F = function { pattern { scale 2 } }
