// checks that rand() stays in sequence when an expression must be re-read (a deprecated name warns)
#version 3.7;
#declare R = seed(11);
#declare D = 1;
#declare I = 0;
#while (I < 4)
  #if (I = 2) #declare deprecated once "D is old" D = 2; #end
  #declare A = rand(R) + D;
  #debug concat(str(A, 0, 6), "\n")
  #declare I = I + 1;
#end
