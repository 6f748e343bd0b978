// checks rgbf (4th value is filter) and rgbt (4th value moves to transmit)
#version 3.7;
#declare A = rgbf <0.1, 0.2, 0.3, 0.4>;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = rgbt <0.1, 0.2, 0.3, 0.4>;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = rgbf 0.5;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = rgbt 0.5;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
#declare E = color rgbf <1, 0.5, 0, 1>;
#debug concat(vstr(5, E, ",", 0, 6), "\n")
