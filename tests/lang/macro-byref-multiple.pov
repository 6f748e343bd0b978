// checks returning several values through by-reference parameters
#version 3.7;
#macro DivMod(A, B, Q, R)
  #declare Q = div(A, B);
  #declare R = mod(A, B);
#end
#declare Quot = 0;
#declare Rem = 0;
DivMod(17, 5, Quot, Rem)
#debug concat(str(Quot, 0, 0), " ", str(Rem, 0, 0), "\n")
#macro Swap(A, B) #local T = A; #declare A = B; #declare B = T; #end
#declare X = "first";
#declare Y = "second";
Swap(X, Y)
#debug concat(X, " ", Y, "\n")
