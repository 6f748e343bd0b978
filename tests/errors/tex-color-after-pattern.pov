// expect: 3:35: a color cannot follow the gradient pattern: use a color_map
#version 3.7;
#declare P = pigment { gradient x rgb 1 }
