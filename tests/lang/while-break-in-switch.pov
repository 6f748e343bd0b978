// checks #break inside a #switch inside a #while: it ends the switch, not the loop
#version 3.7;
#declare I = 0;
#while (I < 4)
  #switch (I)
    #case (1)
      #debug "one "
      #break
    #else
      #debug concat(str(I, 0, 0), " ")
  #end
  #declare I = I + 1;
#end
#debug "\n"
