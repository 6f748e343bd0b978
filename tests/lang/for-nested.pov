// checks nested #for loops
#version 3.7;
#for (I, 1, 3)
  #for (J, I, 3)
    #debug concat("(", str(I, 0, 0), ",", str(J, 0, 0), ")")
  #end
  #debug "\n"
#end
