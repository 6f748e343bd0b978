// checks that a macro sees the locals of the macro that called it (dynamic scoping)
#version 3.7;
#macro Callee()
  #debug concat("callee sees V=", str(V, 0, 0), "\n")
#end
#macro Caller(V)
  Callee()
#end
#macro Caller2()
  #local V = 77;
  Callee()
#end
Caller(5)
Caller2()
#declare V = 1;
Callee()
