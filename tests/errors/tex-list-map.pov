// expect: 3:32: the checker pattern takes a list of entries, not a color_map
#version 3.7;
#declare P = pigment { checker color_map { [0 rgb 0] [1 rgb 1] } }
