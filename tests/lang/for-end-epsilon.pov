// for-end-epsilon.pov: a #for loop runs while its summed variable is
// within 1e-10 past the end (the expected output is what POV-Ray 3.7.0.10
// prints for this program).
#version 3.7;
#macro Count(Name, A, B, S)
	#local N = 0;
	#for (Y, A, B, S) #local N = N + 1; #end
	#debug concat(Name, " ", str(N, 0, 0), "\n")
#end
Count("a", 0.78, 0.93, 0.01)
Count("b", 0, 1, 0.1)
Count("d", 0, 0.9999999, 0.1)
Count("g", 0.93, 0.78, -0.01)
Count("q", 0.78, 0.93 - 1e-12, 0.01)
Count("r", 0.78, 0.93 - 1e-9, 0.01)
Count("e09", 0.78, 0.93 - 0.9e-10, 0.01)
Count("e11", 0.78, 0.93 - 1.1e-10, 0.01)
Count("down09", 0.93, 0.78 + 0.9e-10, -0.01)
Count("down11", 0.93, 0.78 + 1.1e-10, -0.01)
Count("s1", 0, 3 - 0.9e-10, 1)
Count("s100", 0, 300 - 1.1e-10, 100)
// The variable is read back each time: changing it changes the loop.
#declare N = 0;
#for (Y, 0, 1, 0.25) #declare N = N + 1; #if (Y = 0.25) #declare Y = 0.8; #end #end
#debug concat("m ", str(N, 0, 0), "\n")
