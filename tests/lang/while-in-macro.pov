// checks a #while loop inside a macro using #local loop variables
#version 3.7;
#macro Factorial(N)
  #local R = 1;
  #local I = 2;
  #while (I <= N)
    #local R = R * I;
    #local I = I + 1;
  #end
  R
#end
#for (K, 0, 8)
  #debug concat(str(K, 0, 0), "! = ", str(Factorial(K), 0, 0), "\n")
#end
