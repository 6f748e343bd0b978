// checks #ifdef after #undef of a local that hides a global
#version 3.7;
#declare Q = 1;
#macro M()
  #local Q = 2;
  #undef Q
  #ifdef (Q) #debug concat("after undef of local, Q=", str(Q, 0, 0), "\n") #end
  #undef Q
  #ifdef (Q) #debug "Q still defined\n" #else #debug "global Q undefined too\n" #end
#end
M()
#ifdef (Q) #debug "Q defined at the end\n" #else #debug "Q undefined at the end\n" #end
