// checks compiled expressions' cached variables across macro calls: a
// loop's variable shadowed by a macro parameter of the same name inside
// the macro, the global again after the call, a #declare in the macro
// writing the global, and #local in a recursive macro
#version 3.7;
#declare X = 1;
#declare N = 0;
#macro Shadow(X) #declare N = N + X * 10; (X + 0.5) #end
#macro Bump() #declare X = X + 100; #end
#declare I = 0;
#while (I < 4)
  #declare A = X * 2 + 1;
  #declare B = Shadow(I + 3);
  #debug concat(str(A, 0, 1), " ", str(B, 0, 1), " ", str(X * 2 + 1, 0, 1), " ", str(N, 0, 0), "\n")
  #if (I = 1) Bump() #end
  #declare I = I + 1;
#end
#macro Down(K)
  #local L = K * 3;
  #if (K > 0) Down(K - 1) #end
  #debug concat("K ", str(K, 0, 0), " L ", str(L, 0, 0), " ", str(L + K, 0, 0), "\n")
#end
Down(3)
#declare Y = 7;
#macro UseY() (Y * 2) #end
#macro WithY(Y) UseY() #end
#debug concat(str(UseY(), 0, 0), " ", str(WithY(50), 0, 0), " ", str(UseY(), 0, 0), "\n")
#undef Y
#declare Y = 9;
#debug concat(str(UseY(), 0, 0), "\n")
// A macro called in the arguments of a call, and again inside it: the
// parameter hides the global only once the call has begun.
#declare Y = 7;
#macro G() #local R = Y * 2; R #end
#macro M(Y, Z) #declare Q = (G()); #debug concat(str(Z, 0, 0), " ", str(Q, 0, 0), " ", str(Y, 0, 0), "\n") #end
M(50, (G()))
M((G()), (G()))
M((G()), (G()))
