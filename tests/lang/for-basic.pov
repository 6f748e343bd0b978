// checks #for with the default step of 1 and the loop variable after the loop
#version 3.7;
#for (I, 1, 5)
  #debug concat("I=", str(I, 0, 0), "\n")
#end
#debug concat("after loop I=", str(I, 0, 6), "\n")
