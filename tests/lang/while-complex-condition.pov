// checks a #while condition combining & and | with comparisons
#version 3.7;
#declare A = 0;
#declare B = 10;
#while ((A < 5) & (B > 6) | (A = 0))
  #debug concat("A=", str(A, 0, 0), " B=", str(B, 0, 0), "\n")
  #declare A = A + 1;
  #declare B = B - 1;
#end
