// functions.inc: f_sine_wave, f_scallop_wave, eval_pigment and the pattern
// functions whose values lucent shares with POV-Ray (agate, crackle, ripples
// and waves are in stdlib-functions-pending).
#version 3.7;
#include "functions.inc"
#for (V, -1, 1, 0.125)
#debug concat(str(V,0,3), " sine ", str(f_sine_wave(V, 2, 1), 0, 8), " scallop ", str(f_scallop_wave(V, 2, 1), 0, 8), "\n")
#end
#for (X, 0, 1.5, 0.25)
#debug concat("hex ", str(X,0,2), " ", vstr(5, f_hexagon(X, 0, X*0.6), ",", 0, 3), "\n")
#end
#macro S(N, V) #debug concat(N, " ", str(V, 0, 8), "\n") #end
#declare Pts = array[4] {<0.3,0.7,1.1>, <-1.25,0.4,2.3>, <0.05,-0.6,-0.35>, <2.7,1.3,-0.8>}
#for (I, 0, 3)
#declare P = Pts[I];
S("sine", f_sine_wave(P.x, 2, 3))
S("scallop", f_scallop_wave(P.x, 2, 3))
S("sine2", f_sine_wave(P.y, 0.5, 0.25))
S("scallop2", f_scallop_wave(P.y, 0.5, 0.25))
S("boxed", f_boxed(P.x,P.y,P.z))
S("bozo", f_bozo(P.x,P.y,P.z))
S("brick", f_brick(P.x,P.y,P.z))
S("bumps", f_bumps(P.x,P.y,P.z))
S("checker", f_checker(P.x,P.y,P.z))
S("cylindrical", f_cylindrical(P.x,P.y,P.z))
S("dents", f_dents(P.x,P.y,P.z))
S("gradientX", f_gradientX(P.x,P.y,P.z))
S("gradientY", f_gradientY(P.x,P.y,P.z))
S("gradientZ", f_gradientZ(P.x,P.y,P.z))
S("granite", f_granite(P.x,P.y,P.z))
#debug concat("hexagon ", vstr(5, f_hexagon(P.x,P.y,P.z), ",", 0, 6), "\n")
S("leopard", f_leopard(P.x,P.y,P.z))
S("mandel", f_mandel(P.x,P.y,P.z))
S("marble", f_marble(P.x,P.y,P.z))
S("onion", f_onion(P.x,P.y,P.z))
S("planar", f_planar(P.x,P.y,P.z))
S("radial", f_radial(P.x,P.y,P.z))
S("spherical", f_spherical(P.x,P.y,P.z))
S("spiral1", f_spiral1(P.x,P.y,P.z))
S("spiral2", f_spiral2(P.x,P.y,P.z))
S("spotted", f_spotted(P.x,P.y,P.z))
S("wood", f_wood(P.x,P.y,P.z))
S("wrinkles", f_wrinkles(P.x,P.y,P.z))
#end
#declare Pg = pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } }
#declare C = eval_pigment(Pg, <0.25, 0, 0>);
#debug concat("eval_pigment ", vstr(5, C, ",", 0, 6), "\n")
