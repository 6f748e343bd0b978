// checks string functions combined: reverse a string, count characters, title case
#version 3.7;
#declare S = "lucent ray tracer";
#declare R = "";
#for (I, strlen(S), 1, -1)
  #declare R = concat(R, substr(S, I, 1));
#end
#debug concat(R, "\n")
#declare N = 0;
#for (I, 1, strlen(S))
  #if (substr(S, I, 1) = "r") #declare N = N + 1; #end
#end
#debug concat("r count: ", str(N, 0, 0), "\n")
#declare T = concat(strupr(substr(S, 1, 1)), substr(S, 2, strlen(S) - 1));
#debug concat(T, "\n")
