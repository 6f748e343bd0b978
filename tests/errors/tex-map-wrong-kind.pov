// expect: 4:47: 'N' is a normal, not a color_map
#version 3.7;
#declare N = normal { bumps 0.5 }
#declare P = pigment { gradient x color_map { N } }
