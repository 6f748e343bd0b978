// checks a macro that updates a global counter on every call
#version 3.7;
#declare Calls = 0;
#macro Count() #declare Calls = Calls + 1; Calls #end
#declare A = Count();
#declare B = Count() + Count();
#debug concat(str(A, 0, 0), " ", str(B, 0, 0), " ", str(Calls, 0, 0), "\n")
