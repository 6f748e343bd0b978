// checks that #declare of a new identifier inside a macro creates a global
#version 3.7;
#macro Make()
  #declare Made_In_Macro = 42;
  #local Local_In_Macro = 43;
#end
Make()
#debug concat("Made_In_Macro=", str(Made_In_Macro, 0, 0), "\n")
#ifdef (Local_In_Macro) #debug "local leaked\n" #else #debug "local gone\n" #end
