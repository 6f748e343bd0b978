// checks a #switch nested inside another #switch, with #break leaving only the inner one
#version 3.7;
#macro F(A, B)
  #switch (A)
    #case (1)
      #switch (B)
        #case (1) #debug "1-1" #break
        #else #debug "1-other"
      #end
      #debug " (after inner)"
      #break
    #case (2)
      #debug "2-any"
      #break
  #end
  #debug "\n"
#end
F(1, 1) F(1, 5) F(2, 1) F(3, 3)
