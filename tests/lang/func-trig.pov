// checks sin cos tan at a range of angles in radians
#version 3.7;
#declare A = -3;
#while (A <= 3)
  #debug concat(str(A, 0, 2), ": ", str(sin(A), 0, 6), " ", str(cos(A), 0, 6), " ", str(tan(A), 0, 6), "\n")
  #declare A = A + 0.75;
#end
#debug concat(str(sin(pi/6), 0, 6), " ", str(cos(pi/3), 0, 6), " ", str(tan(pi/4), 0, 6), "\n")
