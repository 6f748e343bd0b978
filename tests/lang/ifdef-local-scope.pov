// checks #ifdef on a macro's locals and parameters, inside and after the macro
#version 3.7;
#macro M(Param)
  #local Loc = 1;
  #ifdef (Param) #debug "in: Param defined\n" #end
  #ifdef (Loc) #debug "in: Loc defined\n" #end
#end
M(5)
#ifdef (Param) #debug "out: Param defined\n" #else #debug "out: Param undefined\n" #end
#ifdef (Loc) #debug "out: Loc defined\n" #else #debug "out: Loc undefined\n" #end
