// checks building a long string in a loop with concat
#version 3.7;
#declare S = "";
#for (I, 1, 20)
  #declare S = concat(S, str(mod(I, 10), 0, 0));
#end
#debug concat(S, " ", str(strlen(S), 0, 0), "\n")
#declare T = "";
#declare I = 0;
#while (I < 5)
  #declare T = concat(T, chr(asc("a") + I), "-");
  #declare I = I + 1;
#end
#debug concat(T, "\n")
