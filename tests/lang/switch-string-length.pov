// checks #switch on a computed float from string functions
#version 3.7;
#macro Kind(S)
  #switch (strlen(S))
    #case (0) #debug "empty\n" #break
    #range (1, 3) #debug concat("short: ", S, "\n") #break
    #else #debug concat("long: ", S, "\n")
  #end
#end
Kind("") Kind("ab") Kind("abcdef")
