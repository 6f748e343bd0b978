// checks that each recursive invocation has its own locals
#version 3.7;
#macro Down(N)
  #local Mine = N * 10;
  #if (N > 0) Down(N - 1) #end
  #debug concat("N=", str(N, 0, 0), " Mine=", str(Mine, 0, 0), "\n")
#end
Down(3)
