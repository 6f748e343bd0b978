// checks redefining a macro: the new definition replaces the old one
#version 3.7;
#macro M() "first" #end
#debug concat(M(), "\n")
#macro M() "second" #end
#debug concat(M(), "\n")
#macro M(A) concat("third ", A) #end
#debug concat(M("arg"), "\n")
