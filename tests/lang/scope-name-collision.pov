// checks the manual's "Identifier Name Collisions" example: locals of includes seen by macros, #declare of existing locals
#version 3.7;
#declare A = 123;
#declare B = rgb <1, 2, 3>;
#declare C = 0;
#macro MyMacro(J, K, L)
  #debug concat("macro: A=", str(A, 0, 0), " D=", str(D, 0, 0), "\n")
  #local B = 7;
  #debug concat("macro: local B=", str(B, 0, 0), "\n")
  #declare C = C + 1;
  #declare D = D + 1;
  #local E2 = D + 100;
  #declare E = E2;
#end
#include "inc/scope-collision.inc"
#debug concat("main: A=", str(A, 0, 0), " C=", str(C, 0, 0), " E=", str(E, 0, 0), "\n")
#debug concat("main: B=", vstr(3, B, ",", 0, 0), "\n")
#ifdef (D) #debug "main: D defined\n" #else #debug "main: D undefined\n" #end
