// checks #ifdef on a file handle while open and after #fclose
#version 3.7;
#ifdef (H) #debug "H defined before open\n" #else #debug "H undefined before open\n" #end
#fopen H "fileio-ifdef-handle.tmp" write
#ifdef (H) #debug "H defined while open\n" #end
#fclose H
#ifdef (H) #debug "H still defined after fclose\n" #else #debug "H undefined after fclose\n" #end
