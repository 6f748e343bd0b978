// functions.inc: f_noise3d, f_snoise3d and f_noise_generator are POV-Ray's
// solid noise (the bozo pattern's), generators 1 and 2; a generator number
// is truncated and taken modulo 4, 0 acting as 1. (Generator 3 is in
// stdlib-functions-pending.)
#version 3.7;
#include "functions.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 9), "\n") #end
#declare Pts = array[6] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>, <2.7,1.3,-0.8>,
	<10.5, -3.2, 7.7>, <-20.1, 0.01, 0.5>}
#for (I, 0, 5)
	#declare P = Pts[I];
	S("noise3d", f_noise3d(P.x, P.y, P.z))
	S("snoise3d", f_snoise3d(P.x, P.y, P.z))
	S("gen 0", f_noise_generator(P.x, P.y, P.z, 0))
	S("gen 1", f_noise_generator(P.x, P.y, P.z, 1))
	S("gen 2", f_noise_generator(P.x, P.y, P.z, 2))
	S("gen 4", f_noise_generator(P.x, P.y, P.z, 4))
	S("gen 2.7", f_noise_generator(P.x, P.y, P.z, 2.7))
	S("gen 6", f_noise_generator(P.x, P.y, P.z, 6))
#end
#declare F = function { f_noise3d(x * 2, y - 1, z) * 0.5 + f_noise_generator(z, x, y, 1) }
S("in a function", F(0.4, 1.7, -2.2))
