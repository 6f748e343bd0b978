// checks nested #if blocks, including inside skipped branches
#version 3.7;
#macro Test(A, B)
  #if (A)
    #if (B) #debug "A and B\n" #else #debug "A not B\n" #end
  #else
    #if (B) #debug "B not A\n" #else #debug "neither\n" #end
  #end
#end
Test(1, 1) Test(1, 0) Test(0, 1) Test(0, 0)
#if (0)
  #if (1) #debug "must not print\n" #end
  #while (1) #debug "must not loop\n" #end
  #switch (1) #case (1) #debug "no\n" #end
#else
  #debug "skipped nested blocks correctly\n"
#end
