// checks a macro body containing loops, switches and nested macro definitions used later
#version 3.7;
#macro Outer(N)
  #for (I, 1, N)
    #switch (I)
      #case (1) #debug "one " #break
      #else #debug concat(str(I, 0, 0), " ")
    #end
  #end
  #debug "\n"
  #macro Made_By_Outer() "inner macro exists" #end
#end
Outer(4)
#debug concat(Made_By_Outer(), "\n")
