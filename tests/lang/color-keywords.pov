// checks the keyword colour form: red green blue filter transmit in any order
#version 3.7;
#declare A = color red 1.0 green 0.5;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = color blue 0.3 red 0.1;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = color red 1 green 1 blue 1 filter 1;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = color transmit 1.0;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
#declare E = color filter 1.0;
#debug concat(vstr(5, E, ",", 0, 6), "\n")
#declare Cyan = color blue 1.0 green 1.0;
#debug concat(vstr(5, Cyan, ",", 0, 6), "\n")
#declare F = colour green 0.25 transmit 0.75;
#debug concat(vstr(5, F, ",", 0, 6), "\n")
