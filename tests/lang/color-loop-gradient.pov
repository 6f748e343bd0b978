// checks colour arithmetic in a loop: a linear blend between two colours
#version 3.7;
#declare C1 = rgbt <1, 0, 0, 0>;
#declare C2 = rgbt <0, 0, 1, 1>;
#for (I, 0, 4)
  #declare T = I / 4;
  #declare C = C1 * (1 - T) + C2 * T;
  #debug concat(str(T, 0, 2), ": ", vstr(5, C, ",", 0, 4), " gray=", str(C.gray, 0, 4), "\n")
#end
