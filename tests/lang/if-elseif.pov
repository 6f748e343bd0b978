// checks #if / #elseif / #else chains: only the first true branch runs
#version 3.7;
#macro Classify(N)
  #if (N < 0)
    #debug "negative\n"
  #elseif (N = 0)
    #debug "zero\n"
  #elseif (N < 10)
    #debug "small\n"
  #elseif (N < 5)
    #debug "never reached\n"
  #else
    #debug "large\n"
  #end
#end
Classify(-3) Classify(0) Classify(3) Classify(10) Classify(1000)
