// checks that #undef removes only the most local version of an identifier
#version 3.7;
#declare A = 1;
#macro M()
  #local A = 2;
  #debug concat("local A=", str(A, 0, 0), "\n")
  #undef A
  #debug concat("after undef A=", str(A, 0, 0), "\n")
#end
M()
#debug concat("global A=", str(A, 0, 0), "\n")
