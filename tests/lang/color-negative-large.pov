// checks that colour components may be negative or above one
#version 3.7;
#declare A = rgb <-1, 2.5, 100>;
#debug concat(vstr(5, A, ",", 0, 6), "\n")
#declare B = rgbt <0.5, 0.5, 0.5, -3>;
#debug concat(vstr(5, B, ",", 0, 6), "\n")
#declare C = rgb 0.5 transmit 3;
#debug concat(vstr(5, C, ",", 0, 6), "\n")
