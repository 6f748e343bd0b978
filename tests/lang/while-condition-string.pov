// checks a #while condition that compares strings
#version 3.7;
#declare S = "";
#while (strlen(S) < 6)
  #declare S = concat(S, "ab");
#end
#debug concat(S, "\n")
#declare T = "a";
#while (T != "aaaa")
  #declare T = concat(T, "a");
#end
#debug concat(T, "\n")
