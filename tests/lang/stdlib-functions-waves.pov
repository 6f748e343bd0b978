// functions.inc: f_ripples and f_waves, and the ripples and waves patterns
// with frequency and phase, through functions evaluated while parsing
// (POV-Ray's ten wave sources), as POV-Ray 3.7 prints them.
#version 3.7;
#include "functions.inc"
#declare R = function { pattern { ripples frequency 1.7 phase 0.35 scale 0.6 } }
#declare W = function { pattern { waves frequency 0.6 phase 0.8 rotate 20*x } }
#macro S(N, V) #debug concat(N, " ", str(V, 0, 10), "\n") #end
#declare Pts = array[6] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>, <2.7,1.3,-0.8>, <-7.5,3.25,12.5>, <0,0,0>}
#for (I, 0, 5)
#declare P = Pts[I];
S("f_ripples", f_ripples(P.x, P.y, P.z))
S("f_waves", f_waves(P.x, P.y, P.z))
S("ripples", R(P.x, P.y, P.z))
S("waves", W(P.x, P.y, P.z))
#end
