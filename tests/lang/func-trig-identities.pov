// checks trig identities over many angles (results rounded to six places)
#version 3.7;
#declare MaxErr = 0;
#for (I, 0, 359, 7)
  #declare A = radians(I);
  #declare MaxErr = max(MaxErr, abs(sin(A)*sin(A) + cos(A)*cos(A) - 1));
  #declare MaxErr = max(MaxErr, abs(sin(2*A) - 2*sin(A)*cos(A)));
  #declare MaxErr = max(MaxErr, abs(atan2(sin(A), cos(A)) - (I <= 180 ? A : A - 2*pi)));
#end
#debug concat("identities hold: ", str((MaxErr < 1e-9), 0, 0), "\n")
