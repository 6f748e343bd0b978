// checks #undef of a global identifier and redeclaring it afterwards
#version 3.7;
#declare A = 5;
#ifdef (A) #debug "A defined\n" #end
#undef A
#ifdef (A) #debug "A still defined\n" #else #debug "A undefined\n" #end
#declare A = "back as a string";
#debug concat(A, "\n")
