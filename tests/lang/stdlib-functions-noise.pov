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
// f_hetero_mf: whole and fractional octaves, T as a
// whole number (0.5 acts as 0, 2 squares the weight, negative as 0),
// negative offsets, other lacunarities and H. (f_ridge and f_ridged_mf
// are in stdlib-functions-pending.)
#declare Q = array[3] {<0.3, 0.7, 1.1>, <2.3, -0.7, 1.9>, <-4.1, 0.2, 0.6>}
#for (I, 0, 2)
	#declare P = Q[I];
	#for (O, 1, 4)
		S("hetero", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, O, 0.5, 0, 2))
		S("hetero T1", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, O, 0.5, 1, 2))
	#end
	S("hetero 2.5", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, 2.5, 0.5, 0, 2))
	S("hetero 3.25 T1", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, 3.25, 0.5, 1, 2))
	S("hetero T.5", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, 6, 0.5, 0.5, 2))
	S("hetero T2", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, 3, 0.5, 2, 2))
	S("hetero T-1", f_hetero_mf(P.x, P.y, P.z, 0.5, 2, 3, -0.5, -1, 2))
	S("hetero lac3", f_hetero_mf(P.x, P.y, P.z, 0.8, 3, 2, 0.3, 0, 1))
#end
