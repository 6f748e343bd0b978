// checks that an include's #local is visible in includes it includes and in macros called from it
#version 3.7;
#macro Show_Lv() #debug concat("macro sees Lv=", str(Lv, 0, 0), "\n") #end
#include "inc/lv-outer.inc"
#ifdef (Lv) #debug "Lv leaked\n" #else #debug "Lv gone\n" #end
