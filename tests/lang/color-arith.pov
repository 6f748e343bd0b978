// checks colour arithmetic on all five components
#version 3.7;
#declare A = rgb <1.0, 0.5, 0.2>;
#debug concat(vstr(5, A*0.9, ",", 0, 6), "\n")
#debug concat(vstr(5, A*<0.9,0.9,0.9>, ",", 0, 6), "\n")
#declare White = rgb <1,1,1>;
#declare LightGray = White*0.8;
#debug concat(vstr(5, LightGray, ",", 0, 6), "\n")
#declare B = rgbft <0.1, 0.2, 0.3, 0.4, 0.5>;
#debug concat(vstr(5, A+B, ",", 0, 6), "\n")
#debug concat(vstr(5, B-A, ",", 0, 6), "\n")
#debug concat(vstr(5, A*B, ",", 0, 6), "\n")
#debug concat(vstr(5, B/2, ",", 0, 6), "\n")
