// checks defining and invoking macros with zero, one and several parameters
#version 3.7;
#macro Hello() #debug "hello\n" #end
#macro Say(S) #debug concat(S, "\n") #end
#macro Sum3(A, B, C) #debug concat(str(A + B + C, 0, 6), "\n") #end
Hello()
Say("said")
Sum3(1, 2, 3.5)
Hello() Hello()
