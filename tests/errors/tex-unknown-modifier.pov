// expect: 3:35: expected a color, a pattern, a pigment modifier or '}', found 'sphere'
#version 3.7;
#declare P = pigment { gradient x sphere { 0, 1 } }
