// checks #undef of an identifier that was never declared (allowed, with a warning)
#version 3.7;
#undef Never_Declared
#ifndef (Never_Declared) #debug "still undefined\n" #end
