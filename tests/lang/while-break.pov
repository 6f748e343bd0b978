// checks #break inside #while (3.7: leaves the innermost loop)
#version 3.7;
#declare I = 0;
#while (1)
  #declare I = I + 1;
  #if (I >= 4) #break #end
  #debug concat("I=", str(I, 0, 0), "\n")
#end
#debug concat("stopped at ", str(I, 0, 0), "\n")
#declare A = 0;
#while (A < 3)
  #declare B = 0;
  #while (1)
    #declare B = B + 1;
    #if (B > A) #break #end
  #end
  #debug concat("A=", str(A, 0, 0), " B=", str(B, 0, 0), "\n")
  #declare A = A + 1;
#end
