// checks #break in the middle of a clause (3.7: jumps to the #end at once)
#version 3.7;
#macro F(N)
  #switch (N)
    #case (1)
      #debug "before"
      #if (N = 1) #break #end
      #debug " after"
    #case (2)
      #debug " two"
  #end
  #debug "\n"
#end
F(1) F(2)
