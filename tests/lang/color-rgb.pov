// checks rgb colours: 3 components given, filter and transmit default to 0
#version 3.7;
#declare C = color rgb <1.0, 0.5, 0.2>;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = rgb <0.1, 0.2, 0.3>;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
#declare E = colour rgb <0.3, 0.2, 0.1>;
#debug concat(vstr(5, E, ",", 0, 6), "\n")
#declare F = rgb 0.4;
#debug concat(vstr(5, F, ",", 0, 6), "\n")
#declare G = rgb x;
#debug concat(vstr(5, G, ",", 0, 6), "\n")
