// checks rand() inside loop expressions keeps POV-Ray's sequence
#version 3.7;
#declare R = seed(7);
#declare R2 = seed(99);
#declare I = 0;
#while (I < 5)
  #declare A = rand(R) * 10 - 5;
  #declare B = 3 + rand(R2);
  #declare C = rand(R) + rand(R2);
  #debug concat(str(A, 0, 6), " ", str(B, 0, 6), " ", str(C, 0, 6), "\n")
  #declare I = I + 1;
#end
