// checks #include inside a macro: the include's #local goes away with the include, its #declare stays
#version 3.7;
#macro Load()
  #include "inc/defines.inc"
  #ifdef (Def_Local) #debug "in macro after include: Def_Local still there\n" #else #debug "in macro after include: Def_Local gone\n" #end
#end
Load()
#debug concat("Def_Global=", str(Def_Global, 0, 0), "\n")
#ifdef (Def_Local) #debug "Def_Local leaked\n" #else #debug "Def_Local gone\n" #end
