// expect: 3:26: expected '[' and the map's first entry, found '}'
#version 3.7;
#declare M = color_map { }
