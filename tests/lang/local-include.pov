// checks that #local in an include file hides a global only until the end of the file
#version 3.7;
#declare A = 123;
#include "inc/scope-local.inc"
#debug concat("after include A=", str(A, 0, 0), "\n")
#ifdef (Only_Here) #debug "Only_Here still defined\n" #else #debug "Only_Here gone\n" #end
#ifdef (Made_Here) #debug concat("Made_Here=", str(Made_Here, 0, 0), "\n") #end
