// checks sequences from several seeds (including negative and fractional seeds)
#version 3.7;
#macro Seq(S)
  #local R = seed(S);
  #debug concat(str(S, 0, 1), ":")
  #for (I, 1, 5) #debug concat(" ", str(rand(R), 0, 8)) #end
  #debug "\n"
#end
Seq(1) Seq(42) Seq(12345) Seq(-5) Seq(2.7) Seq(1000000) Seq(-2147483647) Seq(2147483647)
