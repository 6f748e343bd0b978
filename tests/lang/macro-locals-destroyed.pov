// checks that macro locals are destroyed at #end and new ones made on every call
#version 3.7;
#macro Counter()
  #ifdef (C) #debug "C exists at start (wrong)\n" #end
  #local C = 1;
  #debug concat("C=", str(C, 0, 0), "\n")
#end
Counter()
Counter()
#ifndef (C) #debug "C not defined after the calls\n" #end
