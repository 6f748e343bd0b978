// checks #if used in the middle of an expression and a vector
#version 3.7;
#declare Big = 1;
#declare V = <1, #if (Big) 100 #else 2 #end, 3>;
#debug concat(vstr(3, V, ",", 0, 0), "\n")
#declare F = 10 + (#if (Big) 5 #else 6 #end);
#debug concat(str(F, 0, 0), "\n")
