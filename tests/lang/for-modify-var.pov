// checks changing the loop variable inside a #for body (allowed; affects the next iteration)
#version 3.7;
#for (I, 0, 10)
  #debug concat(str(I, 0, 0), " ")
  #declare I = I + 2;
#end
#debug concat("\nafter: ", str(I, 0, 0), "\n")
