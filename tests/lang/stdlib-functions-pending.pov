// functions.inc: the functions whose values lucent does not share with
// POV-Ray yet (listed in pending.list): f_comma and f_helical_torus
// (approximations; f_ridged_mf is in stdlib-functions-ridged); agate, crackle,
// f_noise_generator with generator 3 (pattern-noise-generator3), f_ridge
// (stdlib-functions-ridge), ripples and waves (stdlib-functions-waves) match.
#version 3.7;
#include "functions.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 6), "\n") #end
#declare Pts = array[4] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>, <2.7,1.3,-0.8>}
#for (I, 0, 3)
#declare P = Pts[I];
S("agate", f_agate(P.x,P.y,P.z))
S("crackle", f_crackle(P.x,P.y,P.z))
S("ng3", f_noise_generator(P.x,P.y,P.z,3))
S("comma", f_comma(P.x, P.y, P.z, 1))
S("helical_torus", f_helical_torus(P.x, P.y, P.z, 1, 0.5, 0.3, 0.8, 0.2, 1.5, 0.7, 0.4, 0.6, 0.9))
#end
