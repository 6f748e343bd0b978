// checks that each inclusion of a file creates fresh locals while globals persist
#version 3.7;
#declare Global_Counter = 0;
#include "inc/scope-twice.inc"
#include "inc/scope-twice.inc"
#include "inc/scope-twice.inc"
#ifdef (Local_Counter) #debug "leaked\n" #else #debug "no leak\n" #end
