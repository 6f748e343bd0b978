// checks a Newton iteration in the language calling a user function and its derivative
#version 3.7;
#declare F = function(a) { a * a * a - 2 * a - 5 }
#declare DF = function(a) { 3 * a * a - 2 }
#declare X0 = 2;
#for (I, 1, 6)
  #declare X0 = X0 - F(X0) / DF(X0);
  #debug concat(str(I, 0, 0), ": ", str(X0, 0, 12), "\n")
#end
