// checks a colour combined with a 3-component vector (vector padded with zeros)
#version 3.7;
#declare C = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#declare D = C + <1,1,1>;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
#declare E = C * <2,2,2>;
#debug concat(vstr(5, E, ",", 0, 6), "\n")
#declare C1 = rgb <1,2,3>;
#declare C2 = rgbf <0,0,0,1>;
#declare F = C1 + C2;
#debug concat(vstr(5, F, ",", 0, 6), "\n")
