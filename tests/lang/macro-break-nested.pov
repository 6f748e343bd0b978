// checks that #break leaves only the innermost loop, switch or macro
#version 3.7;
#macro M()
  #for (I, 1, 5)
    #if (I = 3) #break #end
    #debug concat("loop ", str(I, 0, 0), "\n")
  #end
  #debug "macro continues after the loop\n"
  #switch (1)
    #case (1)
      #debug "in switch\n"
      #break
      #debug "never\n"
  #end
  #debug "macro continues after the switch\n"
  #break
  #debug "never\n"
#end
M()
#debug "main continues after the macro\n"
#for (A, 1, 2)
  #for (B, 1, 3)
    #if (B = 2) #break #end
    #debug concat(str(A, 0, 0), "-", str(B, 0, 0), "\n")
  #end
#end
