// checks the first 20 numbers of the stream seeded with 0, printed with 10 decimals
#version 3.7;
#declare R = seed(0);
#for (I, 1, 20)
  #debug concat(str(rand(R), 0, 10), "\n")
#end
