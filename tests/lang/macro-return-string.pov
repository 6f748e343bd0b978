// checks a macro returning a string expression
#version 3.7;
#macro Greet(Name) concat("Hello, ", Name, "!") #end
#macro Pad(N) str(N, -4, 0) #end
#debug concat(Greet("World"), "\n")
#declare G = Greet("POV");
#debug concat(G, " ", Pad(7), "\n")
