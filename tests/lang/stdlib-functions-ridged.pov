// functions.inc: f_ridged_mf (Musgrave's ridged multifractal) against
// POV-Ray 3.7, over fractional octave counts (rounded up), generators 2
// and 3, and two offsets and gains. POV-Ray weighs the octaves by what it
// computed at its first call of f_ridged_mf (fn_internal.c): the first
// call here has the H and lacunarity of all the others and more octaves.
#version 3.7;
#include "functions.inc"
#declare Pts = array[3] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <2.7,1.3,-0.8>}
#debug concat(str(f_ridged_mf(0,0,0, 0.5, 2, 8, 0.9, 2, 2),0,10), "\n")
#for (I, 0, 2)
#declare P = Pts[I];
#for (O, 0, 4.5, 0.5)
#debug concat(str(O,0,1), " ", str(f_ridged_mf(P.x,P.y,P.z, 0.5, 2, O, 0.9, 2, 2),0,10), "\n")
#debug concat(str(O,0,1), " ", str(f_ridged_mf(P.x,P.y,P.z, 0.5, 2, O, 1.1, 1.5, 3),0,10), "\n")
#end
#end
