// expect: 5:18: a color_map has at most 256 entries
#version 3.7;
#declare I = 0;
#declare M = color_map {
#while (I < 300) [I / 300 rgb I / 300] #declare I = I + 1; #end
}
