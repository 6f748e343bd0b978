// checks a #for loop inside a macro: the loop variable is local to the macro
#version 3.7;
#macro Sum(N)
  #local S = 0;
  #for (K, 1, N)
    #local S = S + K;
  #end
  S
#end
#debug concat(str(Sum(10), 0, 0), " ", str(Sum(100), 0, 0), "\n")
#ifdef (K) #debug "K leaked\n" #else #debug "K is local to the macro\n" #end
