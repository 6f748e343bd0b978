// checks string parameters, including ones built by concat and str, passed through nested macros
#version 3.7;
#macro Wrap(S) concat("<", S, ">") #end
#macro Twice(S) concat(Wrap(S), Wrap(S)) #end
#debug concat(Twice("a"), " ", Twice(str(3.5, 0, 1)), " ", Wrap(concat("x", "y")), "\n")
