// checks several ways to declare the same colour
#version 3.7;
#declare A = rgb <1, 0, 0>;
#declare B = color red 1;
#declare C = colour rgbft <1, 0, 0, 0, 0>;
#declare D = <1, 0, 0, 0, 0>;
#declare E = color A;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#debug concat(vstr(5, D, ",", 0, 6), "\n")
#debug concat(vstr(5, E, ",", 0, 6), "\n")
#declare Diff = A - B;
#debug concat(vstr(5, Diff, ",", 0, 6), "\n")
