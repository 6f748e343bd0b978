// expect: 4:25: function S takes 1 argument, not 2
#version 3.7;
#declare S = function { spline { linear_spline 0, <1,2,3> 1, <3,4,5> } }
#declare F = function { S(x, y).x }
