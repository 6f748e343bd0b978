// checks rgbft with 5 components and float promotion
#version 3.7;
#declare A = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = rgbft 0.25;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = color rgbft <1, 1, 1, 0, 1>;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
#declare D = <0.5, 0.6, 0.7, 0.8, 0.9>;
#debug concat(vstr(5, D, ",", 0, 6), "\n")
