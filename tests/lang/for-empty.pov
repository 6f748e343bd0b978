// checks #for loops that run zero times and the variable they leave behind
#version 3.7;
#for (I, 5, 1)
  #debug "must not print\n"
#end
#debug concat("I after empty loop=", str(I, 0, 6), "\n")
#for (J, 1, 5, -1)
  #debug "must not print\n"
#end
#debug concat("J after empty loop=", str(J, 0, 6), "\n")
#for (K, 3, 3)
  #debug concat("single iteration K=", str(K, 0, 0), "\n")
#end
#debug concat("K after=", str(K, 0, 6), "\n")
