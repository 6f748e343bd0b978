// checks #switch with #case, #break and #else
#version 3.7;
#macro Name(N)
  #switch (N)
    #case (1) #debug "one\n" #break
    #case (2) #debug "two\n" #break
    #case (3) #debug "three\n" #break
    #else #debug "other\n"
  #end
#end
Name(1) Name(2) Name(3) Name(4) Name(0)
