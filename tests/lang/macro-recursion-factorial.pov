// checks a recursive macro computing factorials
#version 3.7;
#macro Fact(N)
  #if (N <= 1)
    1
  #else
    N * Fact(N - 1)
  #end
#end
#for (I, 0, 10)
  #debug concat(str(I, 0, 0), "! = ", str(Fact(I), 0, 0), "\n")
#end
