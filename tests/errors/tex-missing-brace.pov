// expect: 4:1: expected a color, a pattern, a pigment modifier or '}', found 'sphere'
#version 3.7;
#declare P = pigment { checker color rgb 1 color rgb 0
sphere { 0, 1 }
