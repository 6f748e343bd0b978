// checks #if with and without #else
#version 3.7;
#if (1) #debug "if 1\n" #end
#if (0) #debug "if 0\n" #end
#if (1) #debug "then\n" #else #debug "else\n" #end
#if (0) #debug "then\n" #else #debug "else\n" #end
#if (2 > 1) #debug "2>1\n" #end
#declare Foo = 0;
#if (Foo) #debug "Foo true\n" #else #debug "Foo false\n" #end
