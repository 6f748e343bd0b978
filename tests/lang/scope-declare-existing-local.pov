// checks that #declare of an existing local assigns the most local version, not the global
#version 3.7;
#declare X = 1;
#macro Outer()
  #local X = 10;
  Inner()
  #debug concat("outer: X=", str(X, 0, 0), "\n")
#end
#macro Inner()
  #declare X = X + 5;
#end
Outer()
#debug concat("global: X=", str(X, 0, 0), "\n")
Inner()
#debug concat("global after Inner: X=", str(X, 0, 0), "\n")
