// checks that a macro's #local D makes a new D hiding the include's D, but "#declare D = D + 1" updates the include's D
#version 3.7;
#macro Bump_Local()
  #local Old = D;
  #local D = Old + 1;
  #debug concat("macro: new local D=", str(D, 0, 0), "\n")
#end
#macro Bump_Declare()
  #declare D = D + 1;
#end
#include "inc/scope-local-macro.inc"
#ifdef (D) #debug "main: D defined\n" #else #debug "main: D undefined\n" #end
