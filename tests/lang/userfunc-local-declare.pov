// checks #local functions inside a macro, and #undef before redeclaring a function
#version 3.7;
#macro Apply(V)
  #local LF = function(a) { a * 3 }
  LF(V)
#end
#debug concat(str(Apply(7), 0, 6), "\n")
#declare G = function(a) { a + 1 }
#debug concat(str(G(1), 0, 6), "\n")
#undef G
#declare G = function(a) { a + 100 }
#debug concat(str(G(1), 0, 6), "\n")
