// checks #ifdef and #ifndef with #else
#version 3.7;
#declare User_Thing = 1;
#ifdef (User_Thing) #debug "User_Thing declared\n" #else #debug "no User_Thing\n" #end
#ifdef (Other_Thing) #debug "Other_Thing declared\n" #else #debug "no Other_Thing\n" #end
#ifndef (User_Thing) #debug "wrong\n" #else #debug "ifndef else\n" #end
#ifndef (Other_Thing) #debug "ifndef Other_Thing\n" #end
