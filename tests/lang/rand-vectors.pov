// checks random vectors built from three draws, as used to place objects
#version 3.7;
#declare R1 = seed(0);
#declare R2 = seed(12345);
#for (I, 1, 5)
  #declare P = <rand(R1), rand(R1), rand(R1)> * 10 - 5;
  #debug concat(vstr(3, P, ",", 0, 6), " r=", str(rand(R2), 0, 6), "\n")
#end
