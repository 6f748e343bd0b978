// math.inc: gradients, divergence and curl, as vectors, floats and functions.
#version 3.7;
#include "math.inc"
#macro S(N, V) #debug concat(N, " ", str(V, 0, 12), "\n") #end
#macro V3(N, V) #debug concat(N, " ", vstr(3, V, ",", 0, 12), "\n") #end
#declare F = function { x*x*y + exp(z) + sin(x*y) }
#declare Fx = function { x*y*y }
#declare Fy = function { sin(x) + z*z*z }
#declare Fz = function { exp(x*z) + y }
#declare P = <0.7, -1.3, 0.4>;
V3("vGradient", vGradient(F, P))
S("Gradient_Length", Gradient_Length(F, P))
S("Gradient_Directional", Gradient_Directional(F, P, <1,2,2>))
S("Divergence", Divergence(Fx, Fy, Fz, P))
V3("vCurl", vCurl(Fx, Fy, Fz, P))
#declare G = fn_Gradient(F);
S("fn_Gradient", G(P.x, P.y, P.z))
#declare GD = fn_Gradient_Directional(F, <1,2,2>);
S("fn_Gradient_Directional", GD(P.x, P.y, P.z))
#declare DV = fn_Divergence(Fx, Fy, Fz);
S("fn_Divergence", DV(P.x, P.y, P.z))
SetGradientAccuracy(0.1)
V3("vGradient 0.1", vGradient(F, P))
#declare G2 = fn_Gradient(F);
S("fn_Gradient 0.1", G2(P.x, P.y, P.z))
#declare H = function { x*x*x + y*y*y*y + z*z*z*z*z }
V3("vGradient H", vGradient(H, <1,1,1>))
S("Gradient_Directional H", Gradient_Directional(H, <1,1,1>, x))
S("Gradient_Directional H unnorm", Gradient_Directional(H, <1,1,1>, 2*x))
S("Div H", Divergence(H, H, H, <1,1,1>))
#declare GH = fn_Gradient(H);
S("fn_Gradient H", GH(1,1,1))
#declare GDH = fn_Gradient_Directional(H, 3*y);
S("fn_Gradient_Directional H", GDH(1,1,1))
#declare DH = fn_Divergence(H, H, H);
S("fn_Divergence H", DH(1,1,1))
