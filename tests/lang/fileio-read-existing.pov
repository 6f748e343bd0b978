// checks #read into identifiers that already exist (globals and a macro local)
#version 3.7;
#fopen F "fileio-read-existing.tmp" write
#write (F, "10, 20, \"new\"\n")
#fclose F
#declare G = 1;
#declare S = "old";
#macro ReadInto()
  #local L = 0;
  #fopen F "fileio-read-existing.tmp" read
  #read (F, G, L, S)
  #fclose F
  #debug concat("in macro L=", str(L, 0, 0), "\n")
#end
ReadInto()
#debug concat("G=", str(G, 0, 0), " S=", S, "\n")
#ifdef (L) #debug "L leaked\n" #else #debug "L stayed local\n" #end
