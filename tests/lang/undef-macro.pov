// checks #undef and #ifdef on a macro name, then redefining the macro
#version 3.7;
#macro M() 1 #end
#ifdef (M) #debug "M defined\n" #end
#undef M
#ifndef (M) #debug "M undefined\n" #end
#macro M() 2 #end
#debug concat(str(M(), 0, 0), "\n")
