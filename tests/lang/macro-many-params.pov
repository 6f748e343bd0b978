// checks a macro with ten parameters of mixed types
#version 3.7;
#macro Ten(A, B, C, D, E, F, G, H, I, J)
  #debug concat(str(A + B + C + D, 0, 0), " ", E, " ", vstr(3, F + G, ",", 0, 0), " ", str(H * I, 0, 0), " ", J, "\n")
#end
Ten(1, 2, 3, 4, "five", <1,1,1>, <2,2,2>, 3, 4, concat("t", "en"))
