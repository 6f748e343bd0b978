// checks colour component keywords followed by expressions
#version 3.7;
#declare K = 0.25;
#declare A = color red K*2 green 1-K blue (K+K)/4 filter K transmit sqrt(K);
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = colour red 1 red 0.5;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
