// checks what seed() returns (the number of the new stream) and that equal seeds give equal sequences
#version 3.7;
#declare A = seed(7);
#declare B = seed(7);
#declare C = seed(99);
#debug concat("streams: ", str(A, 0, 0), " ", str(B, 0, 0), " ", str(C, 0, 0), "\n")
#for (I, 1, 5)
  #debug concat(str(rand(A), 0, 8), " ", str(rand(B), 0, 8), "\n")
#end
