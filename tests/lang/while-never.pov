// checks a #while whose condition is false at the start (body skipped entirely)
#version 3.7;
#declare I = 10;
#while (I < 5)
  #debug "must not print\n"
  #declare I = I + 1;
#end
#debug concat("I=", str(I, 0, 0), "\n")
