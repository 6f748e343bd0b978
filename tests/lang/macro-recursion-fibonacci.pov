// checks a doubly recursive macro computing Fibonacci numbers
#version 3.7;
#macro Fib(N)
  #if (N < 2)
    #local R = N;
  #else
    #local R = Fib(N - 1) + Fib(N - 2);
  #end
  R
#end
#for (I, 0, 15)
  #debug concat(str(Fib(I), 0, 0), " ")
#end
#debug "\n"
