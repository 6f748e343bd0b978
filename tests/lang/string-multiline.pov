// checks string literals that span lines (the line break is part of the string)
#version 3.7;
#declare S = "ab
cd";
#debug concat("[", S, "] ", str(strlen(S), 0, 0), "\n")
#declare T = 1;
#debug concat(str(T, 0, 0), "\n")
