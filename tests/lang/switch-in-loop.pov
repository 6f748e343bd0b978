// checks #switch inside a #for loop, and #break inside a #switch not ending the loop
#version 3.7;
#for (I, 0, 5)
  #switch (I)
    #case (0) #debug "zero " #break
    #range (1, 2) #debug "low " #break
    #case (3) #debug "three "
    #case (4) #debug "three-or-four " #break
    #else #debug "high "
  #end
#end
#debug "\n"
