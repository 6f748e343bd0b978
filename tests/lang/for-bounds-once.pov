// checks that Start, End and Step are evaluated only once
#version 3.7;
#declare Limit = 3;
#declare Calls = 0;
#macro GetLimit() #declare Calls = Calls + 1; Limit #end
#for (I, 1, GetLimit())
  #declare Limit = 10;
  #debug concat(str(I, 0, 0), " ")
#end
#debug concat("\nCalls=", str(Calls, 0, 0), "\n")
