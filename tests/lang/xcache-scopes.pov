// checks a loop expression resolving names through #local scopes of macros
#version 3.7;
#declare K = 100;
#macro Add(N)
  #local K = N;
  #local S = 0;
  #local J = 0;
  #while (J < 3)
    #local S = S + K + J;
    #local J = J + 1;
  #end
  S
#end
#declare I = 0;
#while (I < 3)
  #declare T = Add(I) + K;
  #debug concat(str(T, 0, 0), "\n")
  #declare I = I + 1;
#end
