// checks the 1000th, 10000th and 100000th draws of a stream (long sequences)
#version 3.7;
#declare R = seed(123);
#for (I, 1, 100000)
  #declare V = rand(R);
  #if (I = 1000 | I = 10000 | I = 100000)
    #debug concat(str(I, 0, 0), ": ", str(V, 0, 10), "\n")
  #end
#end
