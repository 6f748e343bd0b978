// expect: 3:58: the checker pattern takes at most 2 colors or pigments
#version 3.7;
#declare P = pigment { checker color rgb 1, color rgb 0, color rgb 1 }
