// checks asin acos atan over their domains
#version 3.7;
#declare A = -1;
#while (A <= 1.0001)
  #debug concat(str(A, 0, 2), ": ", str(asin(A), 0, 6), " ", str(acos(A), 0, 6), " ", str(atan(A), 0, 6), "\n")
  #declare A = A + 0.25;
#end
#debug concat(str(atan(100), 0, 6), " ", str(atan(-1000), 0, 6), "\n")
