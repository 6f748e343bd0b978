// checks that a float added to or multiplying a colour affects filter and transmit too
#version 3.7;
#declare C = rgb <0.2, 0.4, 0.6>;
#declare E = C + 0.5;
#debug concat(vstr(5, E, ",", 0, 6), "\n")
#declare F = 0.5 + C;
#debug concat(vstr(5, F, ",", 0, 6), "\n")
#declare G = C - 1;
#debug concat(vstr(5, G, ",", 0, 6), "\n")
#declare H = rgbt <1,1,1,0.5> * 2;
#debug concat(vstr(5, H, ",", 0, 6), "\n")
