// A #local whose value comes from a macro that has #locals of its own
// binds in the declaring macro, also on a second call (when the returned
// expression is read from its compiled form) and when the next directive
// is an #if. (Found by colors.inc's CRGB2HSV.)
#version 3.7;
#macro Inner(A)
	#local H = A * 2;
	(60 * H)
#end
#macro Outer(A)
	#local G = Inner(A);
	#if (1) #debug "in if\n" #end
	#ifdef (G) #debug "G defined\n" #else #debug "G lost\n" #end
	#declare H = 5;
	(G + A)
#end
#debug concat(str(Outer(1), 0, 1), "\n")
#debug concat(str(Outer(2), 0, 1), "\n")
#debug concat(str(Outer(3), 0, 1), " H=", str(H, 0, 1), "\n")
