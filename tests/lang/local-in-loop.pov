// checks #local inside a #while loop in the main file (acts like #declare) and in a macro
#version 3.7;
#local I = 0;
#while (I < 3)
  #local Sq = I * I;
  #local I = I + 1;
#end
#debug concat("I=", str(I, 0, 0), " Sq=", str(Sq, 0, 0), "\n")
#macro Loop()
  #local J = 0;
  #while (J < 4) #local J = J + 1; #end
  J
#end
#debug concat("Loop()=", str(Loop(), 0, 0), "\n")
#ifdef (J) #debug "J leaked\n" #else #debug "J local\n" #end
