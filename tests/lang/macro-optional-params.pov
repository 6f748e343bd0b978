// checks macros called with an empty argument list and idioms for defaults via #ifndef
#version 3.7;
#macro Opt()
  #ifndef (Opt_Size) #local Opt_Size = 1; #end
  #debug concat("size=", str(Opt_Size, 0, 0), "\n")
#end
Opt()
#declare Opt_Size = 5;
Opt()
