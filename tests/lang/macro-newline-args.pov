// checks a macro call with arguments spread over lines and with comments between them
#version 3.7;
#macro Add3(A, B, C) (A + B + C) #end
#declare S = Add3(
  1,   // first
  2 /* second */ ,
  3
);
#debug concat(str(S, 0, 0), "\n")
#declare T = Add3 (4, 5, 6);
#debug concat(str(T, 0, 0), "\n")
