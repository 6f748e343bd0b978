// checks that by-value parameters live in the macro's local table (a #local of the same name replaces them)
#version 3.7;
#macro M(P)
  #debug concat("P=", str(P, 0, 0), "\n")
  #local P = P * 10;
  #debug concat("P=", str(P, 0, 0), "\n")
  #declare P = P + 1;
  #debug concat("P=", str(P, 0, 0), "\n")
#end
M(3)
#ifdef (P) #debug "P leaked\n" #else #debug "P not global\n" #end
