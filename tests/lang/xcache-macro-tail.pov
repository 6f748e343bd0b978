// checks a macro whose body ends in an expression, used in different contexts
#version 3.7;
#macro Twice(A) 2 * A #end
#declare I = 0;
#while (I < 4)
  #declare X = Twice(I);
  #declare Y = Twice(I) + 1;
  #declare Z = Twice(I) * Twice(2);
  #declare V = <Twice(I), 1, 0>;
  #debug concat(str(X, 0, 0), " ", str(Y, 0, 0), " ", str(Z, 0, 0), " ", vstr(3, V, ",", 0, 0), "\n")
  #declare I = I + 1;
#end
