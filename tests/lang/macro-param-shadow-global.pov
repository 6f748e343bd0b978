// checks that a parameter hides a global of the same name only inside the macro
#version 3.7;
#declare N = "global";
#macro Show(N) #debug concat("param N=", str(N, 0, 0), "\n") #end
Show(42)
#debug concat("global N=", N, "\n")
