// checks that a copy of a stream identifier draws from the same stream (it is just the stream number)
#version 3.7;
#declare R1 = seed(31);
#declare R2 = R1;
#for (I, 1, 3)
  #debug concat(str(rand(R1), 0, 8), " ", str(rand(R2), 0, 8), "\n")
#end
#declare R3 = seed(31);
#for (I, 1, 6) #debug concat(str(rand(R3), 0, 8), " ") #end
#debug "\n"
