// checks a stream seeded in a macro (#local) and used by later calls through a global stream number
#version 3.7;
#macro Init() #local S = seed(77); #declare Stream = S; #end
#macro Draw() rand(Stream) #end
Init()
#for (I, 1, 5) #debug concat(str(Draw(), 0, 8), " ") #end
#debug "\n"
