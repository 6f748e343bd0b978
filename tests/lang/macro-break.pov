// checks #break inside a macro (3.7: ends the macro early)
#version 3.7;
#macro Early(N)
  #debug "start"
  #if (N > 0) #break #end
  #debug " end"
#end
Early(1) #debug "\n"
Early(0) #debug "\n"
