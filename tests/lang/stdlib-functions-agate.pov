// functions.inc: f_agate, f_crackle and f_noise_generator with generator 3
// at a few points (f_comma and f_helical_torus, once listed here, are in
// stdlib-functions-comma).
#version 3.7;
#include "functions.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 6), "\n") #end
#declare Pts = array[4] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>, <2.7,1.3,-0.8>}
#for (I, 0, 3)
#declare P = Pts[I];
S("agate", f_agate(P.x,P.y,P.z))
S("crackle", f_crackle(P.x,P.y,P.z))
S("ng3", f_noise_generator(P.x,P.y,P.z,3))
#end
